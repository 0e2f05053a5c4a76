"""vtu.py - the frame readers that tools/validate_eqip imports from here, now in cdmpm_tools.frames (docs/tools.md).
New commands import from cdmpm_tools; this file goes once tools/validate_eqip does.
"""
from cdmpm_tools.frames import read_pvd, read_vtu  # noqa: F401
