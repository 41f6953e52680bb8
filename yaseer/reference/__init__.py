"""Independent reference models of yaseer: real links and joints, solved directly.

- :mod:`.arithmetic` -- the number types (float, mpmath at a chosen precision);
- :mod:`.elements` -- points, bodies, constraints (pin, slider, angle lock, drivers), loads;
- :mod:`.solver` -- the constraint-based planar multibody solver (Newton positions,
  analytic velocities and accelerations, Lagrange-multiplier forces);
- :mod:`.basic_linkages` -- Programs 1, 2, 3's kinematics in the contract's conventions;
- :mod:`.programs` -- Programs 1, 2, 3 in full (masses, loads, the Q unknown), by input name;
- :mod:`.paper_mechanisms` -- the paper's five example mechanisms;
- :mod:`.seeds` -- the seed papers' linkages.

Nothing here uses yaseer.linkages or the BASIC machine; see docs/reference.md.
"""
