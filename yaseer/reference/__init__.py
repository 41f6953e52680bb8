"""Independent reference models: a constraint-based planar multibody solver (:mod:`.solver`),
the paper's five example mechanisms as real links and joints (:mod:`.paper_mechanisms`) and
the seed papers' linkages (:mod:`.seeds`).  Nothing here uses yaseer.linkages or the BASIC
machine; see docs/reference.md.
"""
