"""Pure planar-linkage numerics. They know nothing of BASIC."""
