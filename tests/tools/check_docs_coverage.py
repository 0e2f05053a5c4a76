#!/usr/bin/python3
"""What the program accepts and writes is documented, and what is documented is exercised by a test.

Asks the built program (it is the authority on what it accepts) and compares with the docs and the tests.
Reports each offence as FILE:LINE: what.

Scene keys
  The keys the scene loader accepts are learned from the program, not from a list kept here: for every
  object of every scene file (scenes/**/*.json, tests/**/*.json) `cdmpm check FILE --set PATH={...,"zz_":1}`
  answers "PATH.zz_: unknown key (allowed: ...)" (src/scene/scene_reader.cpp, SceneReader::object), and a
  typed object's `"type": "zz_"` answers with the registered types, each of which is then learned the same
  way. An object that takes any name (materials, parameters) is recognised by its answer. A key a scene
  file holds that no list names (`parameters`, resolved before loading) counts as accepted when a scene
  with it passes `cdmpm check`. Offences:
    - a key accepted but not documented, or documented but not accepted. Documented keys are the keys in
      backticks in the first column of the Markdown tables headed "key" and in the column headed "keys"
      (tables "type | keys"), in docs/scenes.md and in the sections of other docs that docs/scenes.md links
      to (docs/ice.md's ice keys). Keys are compared by name;
    - a registered type value ("box", "wave_gauge", ...) that docs/scenes.md (or those sections) does not
      name as `"type"`;
    - a key or type value that no scene or test exercises: not in a JSON file of scenes/ or tests/, not in
      a `--set` path, and not a quoted key in a test source (tests/**, scenes/*.set, and the tools whose
      path a test names, such as tools/dem_to_scene.py). This check's own scenes do not count.
CLI
  The subcommands of `cdmpm --help` and the options of `cdmpm SUB --help`: each option must appear in
  docs/running.md (the command-line reference), each subcommand as `cdmpm SUB` there, and each subcommand
  must be run by a test (tests/CMakeLists.txt, tests/**, tools/), this check aside. (Options the docs name
  that this build lacks, such as the MPI build's --rebalance, are not offences.)
Output columns
  Every CSV file the program writes (the *.csv names in src/ and app/, and whatever the runs below write):
  two small scenes written to a temporary folder (2D and 3D: water, ice with crevasses, a rigid block,
  bathymetry with a shore, a georeference, gridded snapshots and one probe of every type the program
  registers, as `cdmpm check` lists them) are run, then `cdmpm linear-waves` on the 2D run. A scene the
  program refuses (a new probe type that needs keys the scenes here do not give it) is an offence. Every
  Markdown table row in docs/ (not the changelog) whose first cell names the file (`hazard.csv`,
  optionally "(2D)" or "(3D)") must list, in backticks, exactly the columns those runs wrote to it (of
  that dimension): a column written but not listed, or listed but not written, is an offence; so is a
  *.csv name in src/ that no run wrote, and a file with no such row. In the probes.csv row, `<name>`
  stands for a probe's name and `<k>` for a station's index.
  The netCDF files written (stations.nc, hazard.nc, ...) are read (their classic-format header): each of
  their variables must be named in backticks in a table row whose first cell names the file.

Usage: /usr/bin/python3 tests/tools/check_docs_coverage.py REPO_ROOT PATH/TO/cdmpm [--verbose]
       (ctest -R Docs.CoverageOfKeysCommandsAndColumns runs it on the build's program)
Exit code 0 when nothing is found, 1 otherwise (2: the check itself could not run).
"""
import glob
import json
import os
import re
import struct
import subprocess
import sys
import tempfile

PROBE = 'zz_'  # a key no scene uses: the loader refuses it and lists what it allows
ENV = dict(os.environ, OMP_WAIT_POLICY='passive')  # no OpenMP re-execution of the program (omp_wait_policy.h)
BACKTICKED = re.compile(r'`([^`]+)`')
IDENT = re.compile(r'^[A-Za-z_][A-Za-z0-9_]*$')
COLUMN = re.compile(r'^[A-Za-z_<][A-Za-z0-9_<>]*$')  # a column, or a pattern such as <name>_eta
UNKNOWN_KEY = re.compile(r'^unknown key \(allowed: (.*)\)$')
ONE_OF = re.compile(r'^expected one of (.*), got ')
VERBOSE = '--verbose' in sys.argv


def note(*args):
    if VERBOSE:
        print(*args, file=sys.stderr)


class Offences:
    def __init__(self, root):
        self.root = root
        self.items = []

    def add(self, where, what):
        file, line = where
        self.items.append((os.path.relpath(file, self.root) if os.path.isabs(file) else file, line, what))

    def report(self):
        for file, line, what in sorted(set(self.items)):
            print(f'{file}:{line}: {what}')
        return 1 if self.items else 0


def read(path):
    with open(path, encoding='utf-8', errors='replace') as f:
        return f.read()


def files_under(root, patterns):
    out = set()
    for p in patterns:
        out.update(f for f in glob.glob(os.path.join(root, p), recursive=True) if os.path.isfile(f))
    return sorted(out)


def first_line_with(root, folders, needle, exts=('.cpp', '.h')):
    """(file, line) of the first code line (not a comment) in folders' sources holding needle, else None."""
    for folder in folders:
        for f in files_under(root, [f'{folder}/**/*{e}' for e in exts]):
            for n, line in enumerate(read(f).splitlines(), 1):
                if needle in line.split('//')[0] and not line.lstrip().startswith('*'):
                    return os.path.relpath(f, root), n
    return None


class Program:
    def __init__(self, path):
        self.path = path

    def run(self, args, cwd=None, timeout=300):
        try:
            r = subprocess.run([self.path] + args, capture_output=True, text=True, env=ENV, cwd=cwd, timeout=timeout)
        except subprocess.TimeoutExpired:
            return 124, '', 'timeout'
        return r.returncode, r.stdout, r.stderr

    def check(self, scene, sets):
        """(exit code, json path, message) of `cdmpm check scene --set ...`; the last error line, split."""
        args = ['check', scene]
        for s in sets:
            args += ['--set', s]
        rc, _, err = self.run(args)
        lines = [l for l in err.splitlines() if l.startswith('cdmpm: error: ')]
        if rc == 0 or not lines:
            return rc, None, err.strip()
        text = lines[-1][len('cdmpm: error: '):]
        if text.startswith(scene + ': '):
            text = text[len(scene) + 2:]
        path, _, message = text.partition(': ')
        return rc, path, message


# ---------------------------------------------------------------- Markdown

def anchor(heading):
    """GitHub's anchor of a heading."""
    text = heading.strip().lower()
    text = re.sub(r'[^a-z0-9 _-]', '', text)
    return text.replace(' ', '-')


def split_row(line):
    body = line.strip()
    if body.startswith('|'):
        body = body[1:]
    if body.endswith('|') and not body.endswith('\\|'):
        body = body[:-1]
    return [c.strip() for c in re.split(r'(?<!\\)\|', body)]


def tables(text, start=0, end=None):
    """Markdown tables of text's lines [start, end): (header cells, [(line number, cells), ...])."""
    lines = text.splitlines()
    end = len(lines) if end is None else end
    i = start
    while i < end:
        if lines[i].lstrip().startswith('|') and i + 1 < end and re.match(r'^\s*\|[\s:|-]+\|\s*$', lines[i + 1]):
            header = [c.lower() for c in split_row(lines[i])]
            rows = []
            j = i + 2
            while j < end and lines[j].lstrip().startswith('|'):
                rows.append((j + 1, split_row(lines[j])))
                j += 1
            yield header, rows
            i = j
        else:
            i += 1


def sections(text):
    """{anchor: (first line index, end line index)} of each heading's section (up to the next heading of its level or above)."""
    lines = text.splitlines()
    heads = []
    fence = False
    for i, l in enumerate(lines):
        if l.startswith('```'):
            fence = not fence
        m = None if fence else re.match(r'^(#+)\s+(.*)$', l)
        if m:
            heads.append((i, len(m.group(1)), anchor(m.group(2))))
    out = {}
    for k, (i, level, a) in enumerate(heads):
        end = next((j for j, lv, _ in heads[k + 1:] if lv <= level), len(lines))
        out[a] = (i, end)
    return out


def scene_doc_parts(root):
    """(path, text, line range) of docs/scenes.md and of the sections of other docs it links to."""
    scenes_md = os.path.join(root, 'docs', 'scenes.md')
    text = read(scenes_md)
    parts = [(scenes_md, text, (0, None))]
    for doc, a in sorted(set(re.findall(r'\]\(([\w-]+\.md)#([\w-]+)\)', text))):
        path = os.path.join(root, 'docs', doc)
        if doc == 'scenes.md' or not os.path.exists(path):
            continue
        other = read(path)
        if a in sections(other):
            parts.append((path, other, sections(other)[a]))
    return parts


def documented_scene_keys(root):
    """{key: [(file, line)]} and {type value: [(file, line)]} named by the scene docs."""
    keys, types = {}, {}
    for path, text, (start, end) in scene_doc_parts(root):
        for header, rows in tables(text, start, end):
            columns = [0] if header[0] == 'key' else [i for i, h in enumerate(header) if h == 'keys']
            for line, cells in rows:
                for c in columns:
                    for tok in BACKTICKED.findall(cells[c] if c < len(cells) else ''):
                        if IDENT.match(tok):
                            keys.setdefault(tok, []).append((path, line))
        lines = text.splitlines()[start:end]
        for n, l in enumerate(lines, start + 1):
            for span in BACKTICKED.findall(l):
                for t in re.findall(r'"(\w+)"', span):
                    types.setdefault(t, []).append((path, n))
    return keys, types


# ---------------------------------------------------------------- scene keys from the program

class SceneDoc:
    def __init__(self, path, data, shipped):
        self.path, self.data, self.dim, self.shipped = path, data, data['dim'], shipped

    def node(self, path):
        n = self.data
        for c in path:
            n = n[c]
        return n


def json_path(path):
    """The loader's spelling of a path: bodies[0].shape."""
    out = ''
    for c in path:
        out += f'[{c}]' if isinstance(c, int) else (('.' if out else '') + c)
    return out


def set_path(path):
    return '.'.join(str(c) for c in path)


def load_json_files(root):
    """{path: parsed JSON} of every JSON file under scenes/ and tests/ that parses."""
    out = {}
    for f in files_under(root, ['scenes/**/*.json', 'tests/**/*.json']):
        try:
            out[f] = json.loads(read(f))
        except ValueError:
            pass
    return out


def type_of(node):
    return node.get('type') if isinstance(node.get('type'), str) else None


def by_signature(item):
    (np_, type_, dim) = item[0]
    return np_, str(type_), dim


class SceneSchema:
    """What the loader accepts, learned from its answers to scenes with one unknown key."""

    def __init__(self, program, docs):
        self.program = program
        self.docs = docs      # shipped scenes first, smaller files first
        self.maps = set()     # normalised paths of objects that take any name (materials)
        self.fixed = {}       # (normalised path, type, dim) -> allowed keys
        self.types = {}       # (normalised path, dim) of a typed object -> registered type names
        self.objects = {}     # (normalised path, dim) -> [(doc, path)] of the objects in the scene files
        self.valid = set()    # scene files that passed `cdmpm check`
        self.extra = {}       # key a shipped scene holds, that no allowed list names, accepted -> normalised path
        self.unlearned = []   # (normalised path, last answer): objects seen only in scenes that fail before them

    def norm(self, path):
        out = ''
        for c in path:
            if isinstance(c, int):
                out += '[]'
            else:
                out += ('.' if out else '') + ('<name>' if out in self.maps else c)
        return out

    def ask(self, doc, path, value, at=None):
        """Put value at path (a new key, or in place of an object) and read the loader's answer about the object at
        `at` (default path): ('keys', [...]), ('types', [...]), ('map',) or ('other', where, message)."""
        path = list(path)
        at = path if at is None else list(at)
        target = f'{PROBE}=1' if not path else f'{set_path(path)}={json.dumps(value, separators=(",", ":"))}'
        rc, where, message = self.program.check(doc.path, [target])
        if rc == 0:
            self.valid.add(doc.path)
            return ('map',)
        if where == json_path(at + [PROBE]):
            m = UNKNOWN_KEY.match(message)
            return ('keys', [k.strip() for k in m.group(1).split(',') if k.strip()]) if m else ('map',)
        m = ONE_OF.match(message or '')
        if where == json_path(at + ['type']) and m:
            return ('types', re.findall(r'"([^"]*)"', m.group(1)))
        return ('other', where, message)

    def crawl(self):
        frontier = [(d, ()) for d in self.docs]
        while frontier:
            groups = {}
            for doc, path in frontier:
                np_ = self.norm(path)
                self.objects.setdefault((np_, doc.dim), []).append((doc, path))
                groups.setdefault((np_, type_of(doc.node(path)), doc.dim), []).append((doc, path))
            for sig, instances in sorted(groups.items(), key=by_signature):
                self.learn_object(sig, instances)
            for (np_, type_, dim), instances in sorted(groups.items(), key=by_signature):
                if type_ is not None and (np_, dim) not in self.types:
                    self.learn_types(np_, dim, instances)
            frontier = [(doc, child) for doc, path in frontier for child in children(doc.node(path), path)]
        self.learn_unseen_types()
        self.learn_unseen_keys()
        self.learn_extra_keys()

    def learn_object(self, sig, instances):
        answer = ()
        for doc, path in instances[:6]:
            answer = self.ask(doc, path, dict(doc.node(path), **{PROBE: 1}))
            if answer[0] == 'map':
                self.maps.add(sig[0])
                return
            if answer[0] == 'keys':
                self.fixed[sig] = answer[1]
                return
        self.unlearned.append((sig[0], answer[1:]))

    def learn_types(self, np_, dim, instances):
        for doc, path in instances[:6]:
            answer = self.ask(doc, path, dict(doc.node(path), type=PROBE))
            if answer[0] == 'types':
                self.types[(np_, dim)] = answer[1]
                return

    def learn_unseen_types(self):
        """A registered type that no scene file uses: learned in place of an object of the same registry."""
        for (np_, dim), names in sorted(self.types.items(), key=lambda x: (-len(self.objects.get(x[0], [])), x[0])):
            registry = [p for (p, d), t in self.types.items() if d == dim and t == names]
            for t in names:
                if any((p, t, dim) in self.fixed for p in registry):
                    continue
                for doc, path in self.objects.get((np_, dim), [])[:6]:
                    answer = self.ask(doc, path, {'type': t, PROBE: 1})
                    if answer[0] == 'keys':
                        self.fixed[(np_, t, dim)] = answer[1]
                        break

    def learn_unseen_keys(self):
        """An allowed key that no scene file holds: what it takes, if an object or an array of objects."""
        for (np_, type_, dim), allowed in sorted(self.fixed.items(), key=by_signature):
            held = {k for doc, path in self.objects.get((np_, dim), []) for k in doc.node(path)}
            for key in allowed:
                sub = f'{np_}.{key}' if np_ else key
                if key in held or key == 'type' or any(p in (sub, sub + '[]') and d == dim for p, _, d in self.fixed):
                    continue
                parents = [(doc, path) for doc, path in self.objects.get((np_, dim), [])
                           if type_of(doc.node(path)) == type_]
                for doc, path in parents[:12]:
                    if self.learn_value(doc, list(path) + [key], sub, dim):
                        break

    def learn_value(self, doc, path, np_, dim):
        """Learns what the key at path takes; False if the scene refused something else first."""
        at, wrap = path, (lambda v: v)
        answer = self.ask(doc, path, {PROBE: 1})
        if answer[0] == 'other' and answer[1] == json_path(path) and answer[2].startswith('expected an array'):
            at, wrap, np_ = path + [0], (lambda v: [v]), np_ + '[]'
            answer = self.ask(doc, path, wrap({PROBE: 1}), at=at)
        if answer[0] == 'keys':
            self.fixed[(np_, None, dim)] = answer[1]
            return True
        if answer[0] == 'other' and answer[1] == json_path(at + ['type']):
            types = self.ask(doc, path, wrap({'type': PROBE}), at=at)
            if types[0] == 'types':
                self.types.setdefault((np_, dim), types[1])
                for t in types[1]:
                    a = self.ask(doc, path, wrap({'type': t, PROBE: 1}), at=at)
                    if a[0] == 'keys':
                        self.fixed[(np_, t, dim)] = a[1]
            return True
        # "expected ..." about the key itself: it takes a value, not an object. Anything else (a key only some
        # parents take, a scene refused elsewhere): try another parent.
        return answer[0] == 'map' or (answer[1] or '').startswith(json_path(path)) and answer[2].startswith('expected')

    def learn_extra_keys(self):
        """A key a shipped scene holds that no allowed list names: accepted if such a scene passes `cdmpm check`."""
        listed = {}
        for (np_, _, _), allowed in self.fixed.items():
            listed.setdefault(np_, set()).update(allowed)
        for (np_, dim), objects in sorted(self.objects.items()):
            if np_ in self.maps or np_ not in listed:
                continue
            for key in sorted({k for doc, path in objects for k in doc.node(path)} - listed[np_]):
                holders = [doc for doc, path in objects if doc.shipped and key in doc.node(path)]
                if key not in self.extra and (any(d.path in self.valid for d in holders) or
                                              any(self.program.check(d.path, [])[0] == 0 for d in holders[:1])):
                    self.extra[key] = np_

    def accepted(self):
        """{key: normalised path of an object that accepts it, the one most often in the scene files}."""
        def count(np_):
            return -sum(len(v) for (p, _), v in self.objects.items() if p == np_)

        out = {}
        for (np_, _, _), allowed in sorted(self.fixed.items(), key=lambda x: (count(x[0][0]), by_signature(x))):
            for k in allowed:
                out.setdefault(k, np_)
        for k, np_ in self.extra.items():
            out.setdefault(k, np_)
        return out

    def registered_types(self):
        """{normalised path: registered type names} over both dimensions."""
        out = {}
        for (np_, _), names in sorted(self.types.items()):
            out.setdefault(np_, [])
            out[np_] += [t for t in names if t not in out[np_]]
        return out


def children(node, path):
    """Paths of the objects directly inside node (its object values, and the objects of its arrays)."""
    for k, v in node.items():
        if isinstance(v, dict):
            yield path + (k,)
        elif isinstance(v, list):
            yield from (path + (k, i) for i, e in enumerate(v) if isinstance(e, dict))


def exercised_names(root, json_files):
    """Names of keys and type values set by a scene file, a --set path or a quoted key in a test source."""
    names = set()
    types = set()
    set_path_re = re.compile(r'(?:--set[\s"\',]+|["\'])([A-Za-z_]\w*(?:\.\w+)+)=')

    def walk(v):
        if isinstance(v, dict):
            for k, x in v.items():
                names.update(c for c in k.split('.') if not c.isdigit())
                if k == 'type' and isinstance(x, str):
                    types.add(x)
                walk(x)
        elif isinstance(v, list):
            for x in v:
                walk(x)
        elif isinstance(v, str):
            m = re.match(r'^([A-Za-z_]\w*(?:\.\w+)+)=(.*)$', v)
            if m:
                names.update(c for c in m.group(1).split('.') if not c.isdigit())
    for data in json_files.values():
        walk(data)
    sources = test_sources(root, ['tests/**/*.cpp', 'tests/**/*.h', 'tests/**/*.py', 'tests/**/*.sh',
                                 'tests/**/*.set', 'tests/CMakeLists.txt', 'scenes/**/*.set'])
    # A tool that a test runs (its path named in tests/), such as the scene writer tools/dem_to_scene.py.
    named = '\n'.join(read(f) for f in sources)
    sources += [f for f in test_sources(root, ['tools/**/*']) if os.path.relpath(f, root) in named]
    for f in sources:
        text = read(f)
        names.update(re.findall(r'\\?["\']([A-Za-z_]\w*)\\?["\']\s*[:,\]}]', text))
        for p in set_path_re.findall(text):
            names.update(c for c in p.split('.') if not c.isdigit())
        if f.endswith('.set'):
            for line in text.splitlines():
                m = re.match(r'^\s*([A-Za-z_][\w.]*)=', line)
                if m:
                    names.update(c for c in m.group(1).split('.') if not c.isdigit())
        types.update(re.findall(r'\\?["\']type\\?["\']\s*[:,]\s*\\?["\'](\w+)\\?["\']', text))
        types.update(re.findall(r'type=\\?"?(\w+)', text))
    return names, types


def check_scene_keys(root, program, offences):
    json_files = load_json_files(root)
    docs = [SceneDoc(f, d, f.startswith(os.path.join(root, 'scenes')))
            for f, d in json_files.items() if isinstance(d, dict) and d.get('dim') in (2, 3)]
    docs.sort(key=lambda d: (not d.shipped, os.path.getsize(d.path), d.path))
    schema = SceneSchema(program, docs)
    schema.crawl()
    for np_, answer in schema.unlearned:
        note(f'not learned: {np_}: {answer}')
    accepted = schema.accepted()
    note(f'{len(accepted)} scene keys accepted, {sum(len(v) for v in schema.types.values())} type values')
    if 'dim' not in accepted or 'time' not in accepted:
        offences.add(('tests/tools/check_docs_coverage.py', 1), 'could not learn the top-level scene keys from '
                     f'`{program.path} check` ({len(accepted)} keys learned)')
        return
    documented, documented_types = documented_scene_keys(root)
    names, used_types = exercised_names(root, json_files)
    scenes_md = ('docs/scenes.md', 1)

    def src(key):
        return first_line_with(root, ['src', 'app'], f'"{key}"') or scenes_md

    for key, np_ in sorted(accepted.items()):
        where = f'{np_}.{key}' if np_ else key
        if key not in documented:
            offences.add(src(key), f'scene key `{key}` ({where}) is accepted but not documented '
                         '(docs/scenes.md: a table headed "key", or "keys")')
        if key not in names:
            offences.add(src(key), f'scene key `{key}` ({where}) is exercised by no scene file, --set or test source')
    for key, places in sorted(documented.items()):
        if key not in accepted:
            for place in places:
                offences.add(place, f'scene key `{key}` is documented but the program accepts no such key')
    registered = {}
    for np_, names in schema.registered_types().items():
        for t in names:
            registered.setdefault(t, np_)
    for t, np_ in sorted(registered.items()):
        if t not in documented_types:
            offences.add(src(t), f'type "{t}" ({np_}.type) is accepted but docs/scenes.md does not name `"{t}"`')
        if t not in used_types:
            offences.add(src(t), f'type "{t}" ({np_}.type) is used by no scene file or test source')


# ---------------------------------------------------------------- command line

def help_section(text, title):
    out, on = [], False
    for line in text.splitlines():
        if re.match(r'^\S.*:$', line):
            on = line[:-1].strip() == title
            continue
        if on:
            out.append(line)
    return out


def help_options(text):
    """The long options of a --help text's "Options:" lines (-h,--help  ...; --out TEXT  ...)."""
    return [o for l in help_section(text, 'Options') if re.match(r'^\s{2}-', l)
            for o in re.findall(r'(?:^\s*|,)(--[a-z][a-z0-9-]*)', l)]


def test_sources(root, patterns):
    """The files of patterns, less this check (its own scenes and commands are no other test's)."""
    return [f for f in files_under(root, patterns) if os.path.abspath(f) != os.path.abspath(__file__)]


def check_cli(root, program, offences):
    rc, top, err = program.run(['--help'])
    subs = [m.group(1) for l in help_section(top, 'Subcommands') for m in [re.match(r'^\s{2}(\S+)\s', l)] if m]
    if rc != 0 or not subs:
        offences.add(('app/main.cpp', 1), f'`cdmpm --help` lists no subcommand (exit code {rc})')
        return
    running = os.path.join(root, 'docs', 'running.md')
    doc = read(running)
    doc_options = set(re.findall(r'(?<![\w-])(--[a-z][a-z0-9-]*)', doc))
    options = {'': help_options(top)}
    for s in subs:
        options[s] = help_options(program.run([s, '--help'])[1])
    for s, opts in options.items():
        for o in opts:
            if o not in doc_options:
                where = first_line_with(root, ['app', 'src'], f'"{o}"') or ('app/main.cpp', 1)
                offences.add(where, f'option `cdmpm {s + " " if s else ""}{o}` is not documented in docs/running.md')
    users = test_sources(root, ['tests/CMakeLists.txt', 'tests/**/*.py', 'tests/**/*.cpp', 'tests/**/*.h',
                               'tests/**/*.sh', 'tools/**/*'])
    texts = []
    for f in users:
        try:
            with open(f, encoding='utf-8') as fh:
                texts.append(fh.read())
        except (UnicodeDecodeError, OSError):
            pass
    for s in subs:
        where = first_line_with(root, ['app'], f'"{s}"') or ('app/main.cpp', 1)
        if not re.search(rf'cdmpm[^\s`]*\s+{re.escape(s)}\b', doc):
            offences.add(where, f'subcommand `cdmpm {s}` is not documented in docs/running.md')
        used = re.compile(rf'["\']{re.escape(s)}["\']|cdmpm\S*\s+{re.escape(s)}\b')
        if not any(used.search(t) for t in texts):
            offences.add(where, f'subcommand `cdmpm {s}` is run by no test (tests/, tools/)')


# ---------------------------------------------------------------- output files

def fixture(dim, probe_types):
    """A small scene of dimension dim that makes the program write every output: water over bathymetry with a
    shore, ice with crevasses (icebergs, crack starts), a rigid block, a georeference, gridded snapshots and one
    probe of each type in probe_types."""
    if dim == 2:
        size, box = [8, 4], lambda lo, hi: {'type': 'box', 'min': lo, 'max': hi}
        bodies = [('ice', box([0, 0], [2, 3])), ('water', box([2, 0], [8, 1.5])), ('block', box([3, 1.5], [3.5, 2]))]
        bed = {'type': 'bathymetry', 'points': [[0, 0], [5, 0], [8, 2.5]]}
        gauges, point, section = [[3], [4]], [4, 0.5], {'position': [4.5]}
        snapshots = {'start': [2], 'spacing': 0.5, 'count': [8]}
    else:
        size, box = [4, 2, 2], lambda lo, hi: {'type': 'box', 'min': lo, 'max': hi}
        bodies = [('ice', box([0, 0, 0], [1, 2, 1.5])), ('water', box([1, 0, 0], [4, 2, 0.75])),
                  ('block', box([2, 0.75, 0.75], [2.5, 1.25, 1.25]))]
        bed = {'type': 'bathymetry', 'origin': [0, 0], 'spacing': [1, 1],
               'heights': [[0, 0, 0, 0.5, 1]] * 3}
        gauges, point, section = [[3, 1], [3.5, 1]], [3, 1, 0.25], {'start': [3, 0.5], 'end': [3, 1.5], 'points': 2}
        snapshots = {'start': [1, 0.25], 'spacing': 0.5, 'count': [4, 3]}
    made = {
        'pressure': lambda: [{'position': point}],
        'wave_gauge': lambda: [{'position': g} for g in gauges],
        'section': lambda: [dict(section)],
        'front': lambda: [{'material': 'ice'}],
        'rigid_position': lambda: [{'material': 'block'}],
        'rigid_velocity': lambda: [{'material': 'block'}],
        'rigid_angle': lambda: [{'material': 'block'}],
    }
    probes = []
    for t in probe_types:  # a type not known here gets a probe without keys: `cdmpm check` says what it lacks
        for i, p in enumerate(made.get(t, lambda: [{}])()):
            probes.append(dict(p, name=f'{t}{i}', type=t))
    ice = {'type': 'ice', 'density': 917, 'youngs_modulus': 1e7, 'poissons_ratio': 0.3, 'M': 1.85, 'beta': 0.3,
           'xi': 3, 'tensile_strength': 1e3}
    scene = {
        'name': f'docs_coverage_{dim}d', 'dim': dim,
        'domain': {'size': size, 'dx': 0.25},
        'time': {'end': 0.02, 'frame_interval': 0.01},
        'materials': {'water': {'type': 'water', 'density': 1000, 'bulk_modulus': 1e5}, 'ice': ice,
                      'block': {'type': 'rigid', 'density': 920, 'bulk_modulus': 1e5}},
        'bodies': [{'material': m, 'particles_per_cell': 4 if dim == 2 else 1, 'shape': s} for m, s in bodies],
        'boundaries': [{'type': 'walls'}, bed],
        'probes': {'interval': 0.005, 'list': probes},
        'output': {'frames': False, 'snapshots': dict(snapshots, times=[0, 0.01])},
        'georeference': {'easting': 500000, 'northing': 7700000, 'crs': 'EPSG:32624'},
    }
    scene['bodies'][0]['crevasses'] = {'seed': 1, 'spacing': 0.5, 'depth': 0.5, 'width': 0.25}
    return scene


def csv_header(path):
    with open(path, encoding='utf-8', errors='replace') as f:
        return [c.strip() for c in f.readline().strip().split(',') if c.strip()]


def netcdf_variables(path):
    """Variable names in a netCDF classic or 64-bit-offset file's header (None if it is not one)."""
    with open(path, 'rb') as f:
        data = f.read(1 << 20)
    if data[:3] != b'CDF' or data[3] not in (1, 2):
        return None
    offset_size = 4 if data[3] == 1 else 8
    pos = 8  # magic, numrecs

    def u32():
        nonlocal pos
        pos += 4
        return struct.unpack('>I', data[pos - 4:pos])[0]

    def name():
        nonlocal pos
        n = u32()
        s = data[pos:pos + n].decode('utf-8', 'replace')
        pos += (n + 3) // 4 * 4
        return s

    sizes = {1: 1, 2: 1, 3: 2, 4: 4, 5: 4, 6: 8}

    def attributes():
        nonlocal pos
        u32()
        for _ in range(u32()):
            name()
            t, n = u32(), u32()
            pos += (n * sizes[t] + 3) // 4 * 4

    u32()  # dimension list tag
    for _ in range(u32()):
        name()
        u32()
    attributes()
    u32()  # variable list tag
    out = []
    for _ in range(u32()):
        out.append(name())
        ndims = u32()
        pos += 4 * ndims  # dimension ids
        attributes()
        pos += 8 + offset_size  # type, vsize, begin
    return out


def output_rows(root):
    """{file name: [(doc path, line, dims, [backticked names])]} of the table rows whose first cell names a file."""
    rows = {}
    for doc in files_under(root, ['docs/**/*.md']):
        if os.path.basename(doc) == 'changelog.md':
            continue
        for header, body in tables(read(doc)):
            for line, cells in body:
                names = BACKTICKED.findall(cells[0])
                if len(names) != 1 or not re.match(r'^[\w.]+\.(csv|nc)$', names[0]):
                    continue
                dims = {2} if '(2D)' in cells[0] else {3} if '(3D)' in cells[0] else {2, 3}
                rest = [t for c in cells[1:] for t in BACKTICKED.findall(c)]
                rows.setdefault(names[0], []).append((doc, line, dims, rest))
    return rows


def column_regex(pattern, probe_names):
    out = ''
    for part in re.split(r'(<[^>]+>)', pattern):
        if part == '<name>':
            out += '(?:' + '|'.join(re.escape(n) for n in sorted(probe_names, key=len, reverse=True)) + ')'
        elif part == '<k>':
            out += r'\d+'
        elif part.startswith('<'):
            out += r'\w+'
        else:
            out += re.escape(part)
    return re.compile('^' + out + '$')


def check_outputs(root, program, offences):
    here = ('tests/tools/check_docs_coverage.py', 1)
    written = {}  # file -> {dim: columns}
    netcdf = {}   # file -> {dim: variables}
    probe_names = set()
    with tempfile.TemporaryDirectory(prefix='docs_coverage_') as tmp:
        for dim in (2, 3):
            scene = fixture(dim, [])
            path = os.path.join(tmp, f'scene_{dim}d.json')
            with open(path, 'w') as f:
                json.dump(scene, f)
            rc, where, message = program.check(path, ['probes.list=[{"name":"a","type":"' + PROBE + '"}]'])
            m = ONE_OF.match(message or '')
            probe_types = re.findall(r'"([^"]*)"', m.group(1)) if m else []
            if not probe_types:
                offences.add(here, f'could not learn the probe types from `cdmpm check`: {where}: {message}')
            scene = fixture(dim, probe_types)
            probe_names.update(p['name'] for p in scene['probes']['list'])
            with open(path, 'w') as f:
                json.dump(scene, f)
            rc, where, message = program.check(path, [])
            if rc != 0:
                offences.add(here, f'the {dim}D scene of check_outputs (fixture) is refused: {where}: {message}')
                continue
            out = os.path.join(tmp, f'out_{dim}d')
            rc, stdout, err = program.run(['run', path, '--out', out, '--threads', '1', '--quiet'], cwd=tmp)
            if rc != 0:
                offences.add(here, f'the {dim}D scene of check_outputs does not run (exit code {rc}): {err.strip()[-300:]}')
                continue
            if dim == 2:
                rc, _, err = program.run(['linear-waves', out, '--depth', '1.5', '--box', '1', '1'])
                if rc != 0:
                    offences.add(here, f'`cdmpm linear-waves` on the 2D scene failed (exit code {rc}): {err.strip()[-300:]}')
            for f in sorted(os.listdir(out)):
                if f.endswith('.csv'):
                    written.setdefault(f, {})[dim] = csv_header(os.path.join(out, f))
                elif f.endswith('.nc'):
                    variables = netcdf_variables(os.path.join(out, f))
                    if variables is not None:
                        netcdf.setdefault(f, {})[dim] = variables
    named = {}
    for f in files_under(root, ['src/**/*.cpp', 'src/**/*.h', 'app/**/*.cpp']):
        for n, line in enumerate(read(f).splitlines(), 1):
            code = line.split('//')[0]
            for name in re.findall(r'"([a-z_]+\.csv)"', code):
                named.setdefault(name, (os.path.relpath(f, root), n))
    for name, where in sorted(named.items()):
        if name not in written:
            offences.add(where, f'{name} is written by the program but by no run of check_outputs: extend its scenes')
    rows = output_rows(root)
    for name, by_dim in sorted(written.items()):
        where = named.get(name, here)
        if name not in rows:
            offences.add(where, f'{name}: its columns are documented in no docs table row whose first cell is `{name}`')
            continue
        for doc, line, dims, listed in rows[name]:
            columns = set()
            for d in dims & set(by_dim):
                columns.update(by_dim[d])
            patterns = {t: column_regex(t, probe_names) for t in listed if COLUMN.match(t)}
            for c in sorted(columns):
                if not any(r.match(c) for r in patterns.values()):
                    offences.add((doc, line), f'{name}: column `{c}` is written but not listed in this row')
            for t, r in sorted(patterns.items()):
                if not any(r.match(c) for c in columns):
                    offences.add((doc, line), f'{name}: `{t}` is listed but the program writes no such column')
    for name, by_dim in sorted(netcdf.items()):
        variables = sorted({v for vs in by_dim.values() for v in vs})
        listed = {t for _, _, _, ts in rows.get(name, []) for t in ts}
        where = rows[name][0][:2] if name in rows else here
        if name not in rows:
            offences.add(where, f'{name}: its variables are documented in no docs table row whose first cell is `{name}`')
            continue
        for v in variables:
            if v not in listed:
                offences.add(where, f'{name}: variable `{v}` is written but not named in its table row')


def main():
    args = [a for a in sys.argv[1:] if a != '--verbose']
    if len(args) != 2:
        print(__doc__.strip().splitlines()[-3], file=sys.stderr)
        return 2
    root, program = os.path.abspath(args[0]), Program(os.path.abspath(args[1]))
    if not os.access(program.path, os.X_OK):
        print(f'{program.path}: not an executable program', file=sys.stderr)
        return 2
    os.chdir(root)
    offences = Offences(root)
    check_scene_keys(root, program, offences)
    check_cli(root, program, offences)
    check_outputs(root, program, offences)
    return offences.report()


if __name__ == '__main__':
    sys.exit(main())
