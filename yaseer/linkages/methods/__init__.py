"""Alternative solution methods for the basic linkages (see registry.py)."""
