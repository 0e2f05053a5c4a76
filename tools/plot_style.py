"""plot_style.py - the names that tools/ensemble, tools/validate_eqip and tools/cliff_stress.py import from here,
now in the package cdmpm_tools (docs/tools.md). New commands import from cdmpm_tools; this file goes once those
three do.
"""
from cdmpm_tools.cli import CDMPM, REPO, fail, output_folder, run_cdmpm  # noqa: F401
from cdmpm_tools.frames import add_frame_arguments, read_material_frame  # noqa: F401
from cdmpm_tools.io import read_asc, read_csv  # noqa: F401
from cdmpm_tools.plotting import ICE_DAMAGE_COLOURS  # noqa: F401
