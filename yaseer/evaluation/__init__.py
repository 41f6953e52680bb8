"""Speed against accuracy (``yaseer bench``) and where methods fail (``yaseer stability``).

- :mod:`.measure`: 50-digit reference values held as float pairs, the error measure.
- :mod:`.virtual_link_reference`: Program 5's 50-digit reference (mpmath).
- :mod:`.cases`: the cases: the seeds' linkages, the paper's five mechanisms.
- :mod:`.ways`: the ways of running a method (per position, one array call, a listing).
- :mod:`.sweeps`: the stability sweeps towards each singular configuration.

The positions and rates of the reference come from :mod:`yaseer.reference` (a
constraint-based multibody solver, Newton-polished at 50 digits, rates from the
differentiated constraints), never from the code under test.
"""
