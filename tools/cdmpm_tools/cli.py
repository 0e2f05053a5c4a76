"""cdmpm_tools.cli - what every command does alike.

  REPO, CDMPM                   the repository's root and its program build/cdmpm;
  fail(tool, message)           one line on stderr and exit status 2, instead of a traceback;
  output_folder(tool, folder)   creates the folder the user named; refuses a folder inside the repository's
                                committed tree (docs/, scenes/, ...) unless --force, so no command overwrites
                                committed figures by default;
  add_output_arguments(ap, help)
                                the options --out FOLDER and --force that output_folder takes;
  run_cdmpm(tool, scene, out)   runs build/cdmpm on a scene with --set values, printing the command; a failed run
                                ends the command with one line (the program's own messages are above it).
"""
import os
import subprocess
import sys

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CDMPM = os.path.join(REPO, "build", "cdmpm")


def fail(tool, message):
    print(f"{tool}: {message}", file=sys.stderr)
    sys.exit(2)


def _tracked_files_under(folder):
    """Committed files of the repository inside FOLDER (empty if FOLDER is outside it or git is missing)."""
    folder = os.path.realpath(folder)
    if os.path.commonpath([folder, REPO]) != REPO:
        return []
    try:
        out = subprocess.run(["git", "-C", REPO, "ls-files", "--", os.path.relpath(folder, REPO)],
                             capture_output=True, text=True, check=True).stdout
    except (OSError, subprocess.CalledProcessError):
        return []
    return out.split()


def output_folder(tool, folder, force=False):
    """Creates FOLDER for a command's outputs and returns it; refuses one that holds committed files."""
    tracked = _tracked_files_under(folder)
    if tracked and not force:
        fail(tool, f"{folder} holds committed files ({tracked[0]}, ...): name another folder, "
                   "or add --force to replace the committed figures on purpose")
    try:
        os.makedirs(folder, exist_ok=True)
    except OSError as e:
        fail(tool, f"cannot create output folder {folder}: {e.strerror}")
    return folder


def add_output_arguments(ap, help):
    """--out FOLDER (described by HELP) and --force, which lets output_folder write into committed files."""
    ap.add_argument("--out", help=help)
    ap.add_argument("--force", action="store_true", help="allow a folder with committed files")


def run_cdmpm(tool, scene, out, threads=None, sets=(), force=True):
    """build/cdmpm run SCENE --out OUT --quiet [--force] [--threads N] [--set S ...]; exits via fail() if it fails."""
    cmd = [CDMPM, "run", scene, "--out", out, "--quiet"] + (["--force"] if force else [])
    if threads:
        cmd += ["--threads", str(threads)]
    for s in sets:
        cmd += ["--set", s]
    print("running:", " ".join(cmd), flush=True)
    if subprocess.run(cmd).returncode != 0:
        fail(tool, f"the run of {os.path.basename(scene)} failed (its messages are above; outputs in {out})")
