#!/usr/bin/python3
"""The repository speaks of its code, physics and results, and its links lead somewhere.

Scans every text file git tracks (docs, README, sources and their comments, tests, tools and the
messages they print, scenes) and reports, as FILE:LINE: what,

  - the word "session" (any case): the repository does not narrate how it was made.
    MPI's own API (MPI_Session_*, mpi::Session) is allowed;
  - an issue number: "issue 20", "issues 17 and 21", "#20" as a reference;
  - a Markdown link [text](target) to a file that does not exist, or to a heading (#anchor)
    that the target Markdown file does not have;
  - a diff or patch file that a Markdown page names but the repository does not hold;
  - a repository path quoted in a Markdown file (`docs/...`, `src/...`, `tools/...`, ...) that names
    a file or folder that does not exist (paths with placeholders such as DIR, N or * are skipped).

Usage: check_docs.py [REPO_ROOT]     (default: the folder above tests/)
Exit code 0 when nothing is found, 1 otherwise.
"""
import html
import os
import re
import subprocess
import sys

# Files that are data, not prose: never scanned.
DATA_SUFFIXES = ('.png', '.jpg', '.jpeg', '.gif', '.svg', '.pdf', '.asc', '.bin', '.vtu', '.pvtu',
                 '.pvd', '.npz', '.npy', '.gz', '.zip')

# This file names the words it looks for.
SELF = 'tests/tools/check_docs.py'
CXX = ('.h', '.cpp', '.c', '.hpp')
SESSION = re.compile(r'session', re.IGNORECASE)
MPI_SESSION = re.compile(r'(MPI_Session|mpi::Session|MPI::Session)')
ISSUE = re.compile(r'\bissues?[\s-]*(?:no\.?\s*)?#?\d+(?:\s*(?:,|and|or)\s*#?\d+)*', re.IGNORECASE)
# "#20" as a reference: a hash and digits after a space or an opening bracket, not a colour
# ("#000000"), a C preprocessor line or a Markdown heading.
HASH_REF = re.compile(r'(?:(?<=\s)|(?<=\()|(?<=\[)|^)#\d{1,5}\b(?![0-9a-fA-F])')
TURN = re.compile(r'\bturn-\d+', re.IGNORECASE)
MD_LINK = re.compile(r'(?<!!)\[[^\]]*\]\(([^)\s]+)(?:\s+"[^"]*")?\)|!\[[^\]]*\]\(([^)\s]+)\)')
QUOTED_PATH = re.compile(r'`((?:docs|src|app|tests|tools|scenes|bench)/[^`\s]*)`')
# A diff or patch named as if it were at hand must be in the repository.
PATCH = re.compile(r'[\w./-]+\.(?:diff|patch)\b')
PLACEHOLDER = re.compile(r'[*?{}<>$]|\bDIR\b|NNNN|\bN\b|_X_|SCENE|RUN|OUT|FOLDER|\bNEW\b|\.\.\.')


def tracked_files(root):
    # Tracked files and new ones not yet added (but not the ignored build and output folders).
    out = subprocess.run(['git', '-C', root, 'ls-files', '-z', '--cached', '--others', '--exclude-standard'],
                         check=True,
                         capture_output=True).stdout.decode('utf-8', 'replace')
    return [f for f in out.split('\0') if f]


def read_text(path):
    try:
        with open(path, 'rb') as f:
            data = f.read()
    except OSError:
        return None
    if b'\0' in data:
        return None
    return data.decode('utf-8', 'replace')


def slug(heading):
    """GitHub's anchor for a Markdown heading."""
    s = html.unescape(heading).strip().lower()
    s = re.sub(r'[^\w\- ]', '', s, flags=re.UNICODE)
    return s.replace(' ', '-')


_anchor_cache = {}


def anchors(path):
    if path not in _anchor_cache:
        text = read_text(path) or ''
        found, counts, in_code = set(), {}, False
        for line in text.splitlines():
            if line.startswith('```'):
                in_code = not in_code
                continue
            m = re.match(r'#{1,6}\s+(.*?)\s*#*\s*$', line)
            if m and not in_code:
                base = slug(m.group(1))
                n = counts.get(base, 0)
                counts[base] = n + 1
                found.add(base if n == 0 else '%s-%d' % (base, n))
        _anchor_cache[path] = found
    return _anchor_cache[path]


def check_link(root, rel, target):
    """What is wrong with a Markdown link target, or None."""
    if re.match(r'^[a-z][a-z0-9+.-]*:', target, re.IGNORECASE):   # http:, https:, mailto:
        return None
    path, _, anchor = target.partition('#')
    if path:
        full = os.path.normpath(os.path.join(root, os.path.dirname(rel), path))
        if not os.path.exists(full):
            return 'link to a file that does not exist: %s' % target
    else:
        full = os.path.join(root, rel)
    if anchor and full.endswith('.md') and os.path.isfile(full):
        if anchor.lower() not in anchors(full):
            return 'link to a heading that %s does not have: %s' % (
                os.path.relpath(full, root), target)
    return None


def check_file(root, rel, text):
    offences = []
    is_md = rel.endswith('.md')
    in_code = False
    for number, line in enumerate(text.splitlines(), 1):
        def say(what):
            offences.append('%s:%d: %s' % (rel, number, what))

        stripped = MPI_SESSION.sub('', line)
        if rel.endswith(CXX):
            # cdmpm::mpi::Session, the class that holds MPI_Init/MPI_Finalize: an identifier, not a label
            stripped = re.sub(r'\bSession\b(?!\s*\d)', '', stripped)
        stripped = stripped.replace('start_new_session', '')   # Python's subprocess API
        for m in SESSION.finditer(stripped):
            word = re.match(r'\w*', stripped[m.start():]).group(0)
            say('the word "%s" (say what was found, and when, instead)' % word)
        for m in ISSUE.finditer(line):
            say('an issue number "%s"' % m.group(0))
        if not (rel.endswith(CXX) and line.lstrip().startswith('#')):
            for m in HASH_REF.finditer(line):
                if is_md and re.match(r'\s*#', line) and m.start() == line.index('#'):
                    continue
                say('an issue reference "%s"' % m.group(0))
        for m in (PATCH.finditer(line) if is_md else ()):
            name = m.group(0)
            if not os.path.exists(name if os.path.isabs(name) and name.startswith(root)
                                  else os.path.join(root, name.lstrip('/'))):
                say('a diff that is not in the repository: %s' % name)
        for m in TURN.finditer(line):
            say('a process label "%s"' % m.group(0))
        if not is_md:
            continue
        if line.startswith('```'):
            in_code = not in_code
            continue
        for m in MD_LINK.finditer(line):
            problem = check_link(root, rel, m.group(1) or m.group(2))
            if problem:
                say(problem)
        if in_code:
            continue
        for m in QUOTED_PATH.finditer(line):
            path = m.group(1).split('#')[0].rstrip('.,:;')
            path = re.split(r'\s|\[|\(', path)[0]
            if PLACEHOLDER.search(path):
                continue
            if not os.path.exists(os.path.join(root, path)):
                say('a path that does not exist: %s' % path)
    return offences


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, '..', '..'))
    offences, scanned = [], 0
    for rel in tracked_files(root):
        if rel.lower().endswith(DATA_SUFFIXES) or rel == SELF:
            continue
        text = read_text(os.path.join(root, rel))
        if text is None:
            continue
        scanned += 1
        offences += check_file(root, rel, text)
    for o in offences:
        print(o)
    print('check_docs: %d files scanned, %d offence%s' % (
        scanned, len(offences), '' if len(offences) == 1 else 's'))
    return 1 if offences else 0


if __name__ == '__main__':
    sys.exit(main())
