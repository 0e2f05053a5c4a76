#!/usr/bin/python3
"""Every command the docs quote runs.

Reads README.md and docs/*.md (not the changelog, which records what was run then) and collects the commands they
quote: each line of a fenced ```bash block (continuation lines joined, comments dropped, `VAR=value` lines expanded
into the lines after them), each line of an unlabelled fenced block that starts with a command of the project, and
each inline `code` span that starts like a command: `build/cdmpm ...`, `tools/NAME ARG...`, `bash tools/...`,
`/usr/bin/python3 tools/...` (or tests/tools/...), `xvfb-run ... tools/...`. A `tools/x.py ARGS` quoted without its
interpreter is run with /usr/bin/python3 when the script is not executable.
Commands of other programs (cmake, ctest, apt-get, gdalinfo, mpirun of a benchmark, `python3 -c`, heredocs) are
not checked; `mpirun ... build-mpi/cdmpm ...` is checked as the serial program's command.

Each command is one of three kinds:

  synopsis  it holds a placeholder: an upper-case word (SCENE, DIR, N, OUT_DIR), `[...]`, `...` or `a | b`.
            Checked without running: every `--option` it names is in the answer of `--help` (`cdmpm SUB --help`,
            `tools/ensemble SUB --help`, a tool's `--help`; for a tool that has no `--help`, its source); for
            `cdmpm run|check` with a scene file, `cdmpm check` accepts the scene with the command's concrete `--set`
            values, and each `--set` whose value is a placeholder names a key the program knows.
  long      a concrete command listed in LONG below (what it produces and how long it takes): checked as a synopsis.
  run       any other command: run in a temporary folder that holds copies of tools/, scenes/, tests/ and docs/
            (added to a git index there, so that a tool refuses to write over them without --force, as in the
            repository) and the program as build/cdmpm, one doc's commands in the doc's order (so that a tool finds
            the run an earlier command made); `output/...` and `/tmp/...` land in the temporary folder. A
            `cdmpm run` gets `--steps 3 --quiet` (unless it names them or its scene is in WHOLE) and the COARSE
            values of its scene; a run `--out DIR` writes to tmp/DIR (and DIR in the rest of its line is that
            folder). It must exit with 0.

A span that quotes `--set path=value` alone must name a path that some shipped scene knows (`cdmpm check` answers
it with no unknown key, parameter or element); `--set PATH=...`, `--set parameters.NAME=...` and
`--set key.path=value` name no path.

Every tool a command names must answer `--help` (exit 0, an argparse usage) or be in NO_HELP, which says how it
runs on a small input instead; shell scripts must pass `bash -n`. The ParaView tools run only where pvpython and
xvfb-run are installed (elsewhere: that they exist).

Usage: /usr/bin/python3 tests/tools/check_docs_commands.py REPO_ROOT PATH/TO/cdmpm [--verbose] [--keep]
       (ctest -R Docs.QuotedCommandsRun runs it on the build's program)
Reports each offence as FILE:LINE: command: what. Exit code 0 when nothing is found, 1 otherwise.
"""
import glob
import os
import re
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
import time

# Concrete commands not run here: the tool or scene prefix, and what it does instead (and how long it takes). An entry
# that no quoted command matches is an offence.
LONG = {
    'bash tools/quickstart.sh': 'installs the packages, builds, runs the default scene (about 4 min)',
    'bash tools/test.sh': 'builds and runs the whole test suite and the MPI build (about 25 min)',
    'bash tools/check_bitwise.sh': 'every shipped scene with two programs (about 20 min)',
    'tools/ensemble run': 'the ensemble members and their bands (7 to 45 min); tests/tools/test_ensemble.py',
    'tools/ensemble calibrate': 'reads a finished ensemble run (tools/ensemble run)',
    'tools/validate_lab': 'the three laboratory scenes and their report (4 to 10 min)',
    'tools/validate_eqip': 'eqip_sermia_2d per seed and its report (5 min to hours)',
    'tools/eqip_2d_to_3d': 'eqip_sermia_block_2d and eqip_sermia_3d (about 30 min)',
    'tools/sweep_sliding_block.py': 'sliding_block_2d at each D/H (10 min to hours)',
    'tools/validate_dam_break.py': 'dam_break_2d at two resolutions (several minutes)',
    'tests/tools/test_handoff.py': 'the ctest Handoff.ShallowWaterFromSnapshotMatchesGauges (about 45 s)',
    'tools/reflection.py': 'needs two runs whose waves reached the layer (time.end=14: minutes)',
    'build/cdmpm run scenes/calving_3d.json': 'the 25-million-particle scale scene (minutes per step)',
    'build/cdmpm run scenes/dam_break_3d.json': 'the benchmark size, 2 million particles (40 s for 10 steps)',
    'build/cdmpm linear-waves': "a finished run's gauge records (wave_celerity_2d: 18 s)",
    'tools/plot_frames.py output/eqip_calibrated_dx5': 'frames 0-8 of the 9-minute run of the calibrated cliff',
}

# Scenes run to their end here, not for 3 steps (a few seconds each), for the tools that read their later frames.
WHOLE = {'ice_shear_2d'}

# Values appended to a run of a scene here (after the command's own), for scenes too big for a few steps.
COARSE = {
    'calving_3d': ['--set', 'parameters.cells_per_H=6'],
    'eqip_sermia_3d': ['--set', 'parameters.dx=60'],
    'eqip_sermia_2d': ['--set', 'parameters.dx=20', '--set', 'time.settle=0.1'],
}

# Tools without --help, and the arguments that run them on a small input ({tmp}: a fresh folder; {frame}, {run}:
# a frame and the folder of the first run here that wrote frames, {nc}: a stations.nc a run here wrote).
NO_HELP = {
    'tools/synthetic_dems.py': ['{tmp}/dems'],
    'tools/runup_linear.py': ['0.1:2.5'],
    'tools/same_particles.py': ['{frame}', '{frame}'],
    'tools/scaling_projection.py': [],
    'tests/tools/cf_rules.py': ['{nc}'],
    'tools/check_vtu_paraview.py': ['{frame}'],  # these two run under ParaView's pvpython (xvfb-run -a pvpython)
    'tools/check_pvd_paraview.py': ['{run}'],
}
PARAVIEW = ('tools/check_vtu_paraview.py', 'tools/check_pvd_paraview.py', 'tools/render_damage_paraview.py')

ENV = dict(os.environ, OMP_WAIT_POLICY='passive', MPLBACKEND='Agg')
LAUNCHERS = (('/usr/bin/python3',), ('python3',), ('bash',), ('xvfb-run', '-a', 'pvpython'), ('pvpython',))
INLINE = re.compile(r'`((?:build/cdmpm |tools/[\w.]+ |bash tools/|/usr/bin/python3 (?:tests/)?tools/|xvfb-run )[^`]*)`')
ANY_PATH = ('key.path',)  # the docs' name for any scene path (docs/scenes.md)
KEY_ERROR = re.compile(r'unknown key|has no parameter|does not exist')
PLACEHOLDER = re.compile(r'(?<![\w./-])(?:[A-Z][A-Z0-9_]*)(?![\w-])|_cN\b|\[|\]|\.\.\.|^\|$')
RUN_ONLY = {'--out': 1, '--threads': 1, '--steps': 1, '--quiet': 0, '--force': 0, '--dry-run': 0, '--ranks': 1,
            '--core-rate': 1, '--resume': 1, '--rebalance': 1, '--gather-output': 0}
MPI_ONLY = {'--rebalance', '--gather-output'}
VERBOSE = '--verbose' in sys.argv
HAVE_PARAVIEW = shutil.which('pvpython') is not None and shutil.which('xvfb-run') is not None


def note(*args):
    if VERBOSE:
        print(*args, file=sys.stderr)


def docs(root):
    files = [os.path.join(root, 'README.md')] + sorted(glob.glob(os.path.join(root, 'docs', '*.md')))
    return [f for f in files if os.path.basename(f) != 'changelog.md']


def fenced_commands(lines):
    """(line, command) of the ```bash blocks: continuations joined, comments dropped, VAR=value expanded."""
    out, in_bash, in_block, heredoc, variables, pending, start = [], False, False, None, {}, '', 0
    lang_of_block = None
    for number, line in enumerate(lines, 1):
        if heredoc is not None:
            if line.strip() == heredoc:
                heredoc = None
            continue
        if line.startswith('```'):
            in_block = not in_block
            lang_of_block = line[3:].strip() if in_block else None
            in_bash = in_block and lang_of_block in ('bash', '')
            variables = {}
            continue
        if not in_bash:
            continue
        if not pending:
            start = number
        text = strip_comment(line)
        if text.endswith('\\'):
            pending += text[:-1] + ' '
            continue
        if text.endswith('|') or text.endswith('&&'):
            pending += text + ' '
            continue
        text, pending = pending + text, ''
        if out and re.match(r'\s+[-\[]', text):  # the options of a synopsis, continued on an indented line
            out[-1] = (out[-1][0], out[-1][1] + ' ' + text.strip())
            continue
        match = re.search(r"<<-?\s*'?(\w+)'?", text)
        if match:
            heredoc = match.group(1)
            continue
        try:
            words = shlex.split(text, comments=True)
        except ValueError:
            words = text.split()
        if not words or (lang_of_block != 'bash' and program_of(words)[0] is None):
            continue
        assignment = re.fullmatch(r'([A-Za-z_]\w*)=(.*)', text.split('#')[0].strip())
        if assignment and len(words) == 1:
            variables[assignment.group(1)] = words[0].split('=', 1)[1]
            continue
        for name, value in variables.items():
            text = re.sub(r'\$\{?%s\b\}?' % name, lambda _m, v=value: v, text)
        out.append((start, text))
    return out


def strip_comment(text):
    """The line without a trailing `# ...` comment (outside quotes)."""
    quote = None
    for i, c in enumerate(text):
        if quote:
            if c == quote:
                quote = None
        elif c in '\'"':
            quote = c
        elif c == '#' and (i == 0 or text[i - 1].isspace()):
            return text[:i].rstrip()
    return text.rstrip()


def prose(lines):
    """The text outside fenced blocks (their lines left empty, so that offsets give line numbers)."""
    kept, in_block = [], False
    for line in lines:
        if line.startswith('```'):
            in_block = not in_block
            kept.append('')
        else:
            kept.append('' if in_block else line)
    return '\n'.join(kept)


def code_spans(lines):
    """(line, text) of every inline `code` span (a span may run over a line break, not over a blank line)."""
    text = prose(lines)
    return [(text.count('\n', 0, m.start()) + 1, ' '.join(m.group(1).split()))
            for m in re.finditer(r'`((?:[^`\n]|\n(?![ \t]*\n))+)`', text)]


def inline_commands(lines):
    return [(number, span) for number, span in code_spans(lines) if INLINE.fullmatch('`%s`' % span)]


def set_spans(lines):
    """(line, [path=value, ...]) of the spans that quote --set values without a command."""
    out = []
    for number, span in code_spans(lines):
        if span.startswith('--set '):
            words = split_words(span)
            out.append((number, [words[k + 1] for k in range(len(words) - 1) if words[k] == '--set']))
    return out


def split_words(command):
    try:
        return shlex.split(command)
    except ValueError:
        return command.split()


def program_of(words):
    """(kind, index of the program word): kind 'cdmpm', 'tool' or None; env assignments and launchers skipped."""
    i = 0
    while i < len(words) and re.fullmatch(r'[A-Za-z_]\w*=.*', words[i]):
        i += 1
    if i < len(words) and words[i] == 'mpirun':
        for j in range(i + 1, len(words)):
            if words[j].endswith('/cdmpm'):
                return 'cdmpm', j
        return None, i
    for launcher in LAUNCHERS:
        if tuple(words[i:i + len(launcher)]) == launcher:
            i += len(launcher)
            break
    if i >= len(words):
        return None, i
    if words[i] == 'build/cdmpm':
        return 'cdmpm', i
    if re.match(r'(tests/)?tools/[\w.-]+$', words[i]):
        return 'tool', i
    if 'build/cdmpm' in words:  # at the end of a pipeline (xargs ... build/cdmpm run ...)
        return 'cdmpm', words.index('build/cdmpm')
    return None, i


def is_option(word):
    return bool(re.match(r'--?[A-Za-z]', word))


def is_placeholder(word):
    """An upper-case word (DIR, N, OUT_DIR), an unexpanded $VAR, [, ], ... or a lone |; a JSON value is none."""
    return word.startswith('$') or ('{' not in word and bool(PLACEHOLDER.search(word)))


def is_synopsis(words):
    return any(is_placeholder(w) for w in words)


LONG_USED = set()


def long_reason(command):
    for prefix, reason in LONG.items():
        bare = prefix.split(' ', 1)[1] if prefix.startswith('bash ') else prefix
        if re.search(r'(^|[\s/])' + re.escape(bare) + r'(\s|$)', command):
            LONG_USED.add(prefix)
            return reason
    return None


class Checker:
    def __init__(self, root, cdmpm, sandbox):
        self.root, self.cdmpm, self.sandbox = root, cdmpm, sandbox
        self.offences, self.helps = [], {}
        self.counts = {'synopsis': 0, 'long': 0, 'run': 0, 'paraview': 0, 'sets': 0}

    def offence(self, where, command, what):
        self.offences.append('%s:%d: %s: %s' % (os.path.relpath(where[0], self.root), where[1], command, what))

    def call(self, argv, cwd=None, timeout=120):
        """(exit code, output) of ARGV; on a timeout its whole process group (a shell line's programs) is ended."""
        p = subprocess.Popen(argv, cwd=cwd or self.sandbox, env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                             text=True, start_new_session=True)
        try:
            output = p.communicate(timeout=timeout)[0]
            return p.returncode, output
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            p.communicate()
            return -1, 'timed out after %d s' % timeout

    def help_text(self, argv):
        key = tuple(argv)
        if key not in self.helps:
            self.helps[key] = self.call(list(argv) + ['--help'], timeout=60)
        return self.helps[key]

    # --- cdmpm ---------------------------------------------------------------------------------------------------
    def check_cdmpm(self, where, command, words, i):
        args = [w.strip('[]') for w in words[i + 1:] if w.strip('[]') not in ('', '...', '|')]
        sub = args[0] if args and not args[0].startswith('-') else None
        rc, text = self.help_text([self.cdmpm] + ([sub] if sub else []))
        if rc != 0:
            self.offence(where, command, 'cdmpm %s --help fails: %s' % (sub or '', text.strip()[-200:]))
            return
        for w in args:
            option = w.split('=', 1)[0]
            if is_option(option) and option not in text and option not in MPI_ONLY:
                self.offence(where, command, 'option %s is not in `cdmpm %s --help`' % (option, sub or ''))
        if sub not in ('run', 'check'):
            return
        scenes, sets, concrete, j = [], [], [], 1
        while j < len(args):
            w = args[j]
            if w == '--set' and j + 1 < len(args):
                sets.append(args[j + 1])
                j += 2
            elif w in RUN_ONLY:
                j += 1 + RUN_ONLY[w]
            elif w.startswith('-'):
                j += 1
            else:
                scenes.append(w)
                j += 1
        scenes = [s for s in scenes if not is_placeholder(s)]
        if not scenes:
            return
        for value in sets:
            (concrete if not is_placeholder(value.split('=', 1)[-1]) else []).append(value)
        argv = [self.cdmpm, 'check'] + scenes + [a for v in concrete for a in ('--set', v)]
        for scene in scenes:
            argv += COARSE.get(os.path.splitext(os.path.basename(scene))[0], [])
        rc, text = self.call(argv)
        if rc != 0 and (len(concrete) == len(sets) or KEY_ERROR.search(text)):  # a placeholder value may be needed
            self.offence(where, command, 'cdmpm check refuses it: %s' % text.strip()[-300:])
        for value in sets:
            if value in concrete:
                continue
            coarse = [a for scene in scenes for a in COARSE.get(os.path.splitext(os.path.basename(scene))[0], [])]
            rc, text = self.call([self.cdmpm, 'check'] + scenes + coarse + ['--set', value])
            if rc != 0 and KEY_ERROR.search(text):
                self.offence(where, command, '--set %s: %s' % (value, text.strip()[-300:]))

    def check_sets(self, where, values, doc_text):
        """--set values quoted alone: each must be accepted by a shipped scene (those the doc names first)."""
        files = glob.glob(os.path.join(self.root, 'scenes', '*.json'))
        texts = {f: open(f).read() for f in files}
        values = [v for v in values if not any(is_placeholder(part) for part in v.split('=', 1)[0].split('.'))
                  and v.split('=', 1)[0] not in ANY_PATH]

        def candidates(value):  # first the scenes that hold the key's name, then those the doc names
            leaf = '"%s"' % [part for part in value.split('=', 1)[0].split('.') if not part.isdigit()][-1]
            return sorted(files, key=lambda f: (leaf not in texts[f],
                                                os.path.splitext(os.path.basename(f))[0] not in doc_text, f))
        if len(values) > 1:  # the span's values together, on the first value's scene: one run when all are known
            scene = candidates(values[0])[0]
            coarse = COARSE.get(os.path.splitext(os.path.basename(scene))[0], [])
            if self.call([self.cdmpm, 'check', scene] + coarse + [a for v in values for a in ('--set', v)])[0] == 0:
                return
        for value in values:
            scenes = candidates(value)
            errors = []
            for scene in scenes:
                coarse = COARSE.get(os.path.splitext(os.path.basename(scene))[0], [])
                rc, text = self.call([self.cdmpm, 'check', scene] + coarse + ['--set', value])
                if rc == 0 or not KEY_ERROR.search(text):  # known keys (a value may need the span's other values)
                    break
                errors.append(text.strip().splitlines()[-1] if text.strip() else 'exit %d' % rc)
            else:
                self.offence(where, '--set ' + value, 'no shipped scene accepts it: %s' % errors[0][-300:])

    # --- tools ---------------------------------------------------------------------------------------------------
    def launcher(self, tool):
        path = os.path.join(self.sandbox, tool)
        if tool.endswith('.sh'):
            return ['bash', path]
        if tool.endswith('.py') or not os.access(path, os.X_OK):
            return ['/usr/bin/python3', path]
        return [path]

    def check_tool(self, where, command, words, i):
        tool = words[i]
        if not os.path.isfile(os.path.join(self.root, tool)):
            self.offence(where, command, '%s does not exist' % tool)
            return
        args = [w.strip('[]') for w in words[i + 1:] if w.strip('[]') not in ('', '...', '|')]
        if tool.endswith('.sh'):
            rc, text = self.call(['bash', '-n', os.path.join(self.root, tool)])
            if rc != 0:
                self.offence(where, command, 'bash -n: %s' % text.strip())
            source = open(os.path.join(self.root, tool)).read()
            for w in args:
                if is_option(w) and w.split('=')[0] not in source:
                    self.offence(where, command, 'option %s is not in %s' % (w, tool))
            return
        base = self.launcher(tool)
        sub = [args[0]] if args and re.fullmatch(r'[a-z]+', args[0]) else []
        rc, text = self.help_text(base + sub) if sub else (1, '')
        if rc != 0 or 'usage' not in text:
            sub = []
            rc, text = self.help_text(base)
        if rc != 0 or 'usage' not in text:
            if tool in PARAVIEW and not HAVE_PARAVIEW:
                note('no ParaView here: only that %s exists' % tool)
                return
            if tool not in NO_HELP:
                self.offence(where, command, '%s does not answer --help (and is not in NO_HELP)' % tool)
                return
            text = open(os.path.join(self.root, tool)).read()
        for w in args:
            option = w.split('=', 1)[0]
            if is_option(option) and option not in text:
                self.offence(where, command, 'option %s is not in %s %s--help' % (option, tool, ' '.join(sub) + ' '))

    def no_help_runs(self, frame, nc):
        for tool, args in NO_HELP.items():
            if tool in PARAVIEW and not HAVE_PARAVIEW:
                continue
            tmp = tempfile.mkdtemp(dir=self.sandbox)
            launcher = ['xvfb-run', '-a', 'pvpython', tool] if tool in PARAVIEW else self.launcher(tool)
            argv = launcher + [a.format(tmp=tmp, frame=frame, run=os.path.dirname(frame), nc=nc) for a in args]
            rc, text = self.call(argv)
            note('NO_HELP', tool, rc)
            if rc != 0:
                self.offences.append('tests/tools/check_docs_commands.py: NO_HELP %s: exit %d: %s'
                                     % (tool, rc, text.strip()[-300:]))

    # --- runs ----------------------------------------------------------------------------------------------------
    def run(self, where, command, words, kind, i):
        text = command.replace('/tmp/', os.path.join(self.sandbox, 'tmp') + '/')
        if kind == 'cdmpm' and 'run' in words[i + 1:i + 2]:
            whole = any(os.path.splitext(os.path.basename(w))[0] in WHOLE for w in words if w.endswith('.json'))
            extra = [] if '--steps' in words or whole else ['--steps', '3']
            extra += [] if '--quiet' in words else ['--quiet']
            for w in words:
                extra += COARSE.get(os.path.splitext(os.path.basename(w))[0], []) if w.endswith('.json') else []
            text += ' ' + ' '.join(shlex.quote(e) for e in extra)  # xargs puts its values after these
        elif kind == 'tool' and i == 0 and not os.access(os.path.join(self.sandbox, words[i]), os.X_OK):
            # `tools/x.py ARGS` quoted for a script that is not executable: run by its interpreter
            text = text.replace(words[i], self.launcher(words[i])[0] + ' ' + words[i], 1)
        began = time.time()
        rc, output = self.call(['bash', '-c', text], timeout=150)
        note('run (%.1f s):' % (time.time() - began), text)
        if rc != 0:
            self.offence(where, command, 'exit %d: %s' % (rc, output.strip()[-400:]))

    def check(self, where, command):
        # `cdmpm run ... --out DIR`: the run is made, into tmp/DIR (and DIR is that folder in the rest of the line)
        out = re.search(r'build/cdmpm run .*--out ([A-Z][A-Z_]*)(?![\w/.])', command)
        if out:
            command = re.sub(r'(?<![\w/.])%s(?![\w/.])' % out.group(1), 'tmp/' + out.group(1), command)
        for part in command.split(' && '):
            self.check_one(where, part.strip())

    def check_one(self, where, command):
        words = split_words(command)
        kind, i = program_of(words)
        if kind is None:
            note('not checked:', command)
            return
        found = len(self.offences)
        if kind == 'cdmpm':
            self.check_cdmpm(where, command, words, i)
        else:
            self.check_tool(where, command, words, i)
        mpi = words[0] == 'mpirun' or any(w.startswith('build-mpi/') for w in words)
        if is_synopsis(words[i:]) or mpi:
            self.counts['synopsis'] += 1
        elif 'pvpython' in words and not HAVE_PARAVIEW:
            self.counts['paraview'] += 1
            note('no ParaView here, not run:', command)
        elif long_reason(command):
            self.counts['long'] += 1
            note('long:', command, '-', long_reason(command))
        else:
            self.counts['run'] += 1
            if len(self.offences) == found:  # refused already: not run
                self.run(where, command, words, kind, i)


def make_sandbox(root, cdmpm):
    sandbox = tempfile.mkdtemp(prefix='cdmpm_docs_commands_')
    for folder in ('tools', 'scenes', 'tests', 'docs'):
        shutil.copytree(os.path.join(root, folder), os.path.join(sandbox, folder),
                        ignore=shutil.ignore_patterns('__pycache__'))
    # the copies as a repository's files, so that a tool refuses to write over them without --force, as it does here
    for git in (['init', '-q'], ['add', '-A']):
        subprocess.run(['git', '-C', sandbox] + git, check=True, capture_output=True)
    os.makedirs(os.path.join(sandbox, 'build'))
    os.symlink(os.path.abspath(cdmpm), os.path.join(sandbox, 'build', 'cdmpm'))
    os.makedirs(os.path.join(sandbox, 'tmp'))
    return sandbox


def main():
    args = [a for a in sys.argv[1:] if not a.startswith('--')]
    if len(args) != 2:
        sys.exit(__doc__)
    root, cdmpm = os.path.abspath(args[0]), os.path.abspath(args[1])
    sandbox = make_sandbox(root, cdmpm)
    checker = Checker(root, cdmpm, sandbox)
    try:
        for path in docs(root):
            lines = open(path, encoding='utf-8').read().split('\n')
            commands = sorted(fenced_commands(lines) + inline_commands(lines))
            for number, command in commands:
                checker.check((path, number), command)
            for number, values in set_spans(lines):
                checker.check_sets((path, number), values, '\n'.join(lines))
                checker.counts['sets'] += 1
        frames = sorted(glob.glob(os.path.join(sandbox, 'output', '*', 'particles_*.vtu')))
        stations = sorted(glob.glob(os.path.join(sandbox, 'output', '*', 'stations.nc')))
        if frames and stations:
            checker.no_help_runs(frames[0], stations[0])
        else:
            checker.offences.append('tests/tools/check_docs_commands.py: no run here wrote a frame and a stations.nc'
                                    ' for NO_HELP')
        for prefix in sorted(set(LONG) - LONG_USED):
            checker.offences.append('tests/tools/check_docs_commands.py: LONG %r: no quoted command is that' % prefix)
    finally:
        if '--keep' in sys.argv:
            print('kept', sandbox)
        else:
            shutil.rmtree(sandbox, ignore_errors=True)
    for line in checker.offences:
        print(line)
    counts = checker.counts
    print('%d commands: %d run, %d long, %d synopses, %d not run for want of ParaView; %d --set quotes; %d offence(s)'
          % (counts['run'] + counts['long'] + counts['synopsis'] + counts['paraview'], counts['run'], counts['long'],
             counts['synopsis'], counts['paraview'], counts['sets'], len(checker.offences)))
    sys.exit(1 if checker.offences else 0)


if __name__ == '__main__':
    main()
