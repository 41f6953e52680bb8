"""The BASIC machine. It knows nothing of mechanisms."""
