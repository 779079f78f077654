#!/usr/bin/env python3
"""True signposts: the project's map and comments point at what is there.

Fails (exit 1, one line per finding: file:line: what; the fix) when
  1. docs/architecture.md names a file or folder that does not exist, or names
     one by a path that does not start at a top-level folder;
  2. a source file names a repository file that does not exist (a path from a
     top-level folder, "station/station_snapshot.cpp", or a bare source file name,
     "station_snapshot.cpp", that no folder holds);
  3. a source file or a Markdown page cites a file outside the repository
     (../shared/spec/..., a spec note such as "frames.md §3" that the repository
     has no page of, STYLE.md, seeds/): a reader of the project cannot open it.
     Cite the project's own docs (docs/*.md) instead, and name a fact's source
     in words ("SLMP Reference Manual, §5.2", "measured on real CPUs").

Usage: check-architecture.py [REPO]   (default: the repository this script is in)
Run by ctest as "signposts: ..." (tests/CMakeLists.txt).
"""
import fnmatch
import os
import re
import subprocess
import sys

ROOT = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))

TOP = ("devicemodel", "protocol", "program", "frontends", "config", "scenarios", "station", "server", "control",
       "tools", "tests", "docs", "scripts", "deploy", "clients", "examples")
SOURCE_EXT = (".cpp", ".hpp", ".h", ".py", ".js", ".lua", ".cmake", ".sh", ".html", ".css")
SOURCE_NAMES = ("CMakeLists.txt", "Dockerfile")

# Files a build makes, named by the sources that make them: not in the tree.
# Keep this list tiny; each entry says who writes it.
GENERATED = {
    "web_files.cpp",          # control/web/embed_web.cmake writes it into the build folder
    "builtin_profiles.cpp",   # config/embed_profiles.cmake writes it into the build folder
}


def tracked_files():
    try:
        out = subprocess.run(["git", "-C", ROOT, "ls-files", "-co", "--exclude-standard"], check=True,
                             capture_output=True, text=True).stdout
        files = [f for f in out.splitlines() if f]
    except (OSError, subprocess.CalledProcessError):
        files = []
        for d, dirs, names in os.walk(ROOT):
            dirs[:] = [x for x in dirs if x not in (".git", "build", "node_modules") and not x.startswith("build")]
            files += [os.path.relpath(os.path.join(d, n), ROOT) for n in names]
    return sorted(f for f in files if "node_modules/" not in f and os.path.isfile(os.path.join(ROOT, f)))


FILES = tracked_files()
BASENAMES = {os.path.basename(f) for f in FILES}
DIRS = {os.path.dirname(f) for f in FILES}
for d in list(DIRS):
    while d:
        d = os.path.dirname(d)
        DIRS.add(d)


def expand_braces(path):
    m = re.search(r"\{([^{}]*)\}", path)
    if not m:
        return [path]
    out = []
    for alt in m.group(1).split(","):
        out += expand_braces(path[:m.start()] + alt + path[m.end():])
    return out


def exists(path):
    """A repository path, with optional * wildcards and {a,b} alternatives."""
    path = path.rstrip("/")
    for p in expand_braces(path):
        if "*" in p:
            if any(fnmatch.fnmatch(f, p) for f in FILES) or any(fnmatch.fnmatch(d, p) for d in DIRS):
                continue
            return False
        if p not in DIRS and not os.path.exists(os.path.join(ROOT, p)):
            return False
    return True


URL = re.compile(r"\b[a-z]+://\S+")
# A path from a top-level folder to a file (it has an extension), a folder (it
# ends in "/") or a pattern ("config/profiles/*.json"); "program/system memory"
# is prose.
REPO_PATH = re.compile(r"(?<![\w./-])((?:%s)/[\w./*{},-]*(?:\.[\w*}]+|/))(?![\w/-])" % "|".join(TOP))
# A bare source file name ("station_snapshot.cpp"), or a backticked stem ("`station_log.*`").
BARE_SOURCE = re.compile(r"(?<![\w./*<-])([A-Za-z_][\w-]*\.(?:cpp|hpp|py|lua|cmake))(?![\w/.-]|\.\w)|`([A-Za-z_][\w-]*\.\*)`")
MD_NAME = re.compile(r"(?<![\w/-])((?:\.\./)*[\w./-]*[\w-]+\.md)\b")
# Citations of what lies outside: the shared folder beside the repository, its
# spec notes (also named without ".md"), its seeds, and "spec §x" (a section of
# a note the repository does not hold).
NOTES = ("hardware-behaviour", "slmp-frames-and-devices", "slmp-labels-remote-misc", "slmp-files",
         "ladder-motion-hostlink", "sharp-jw51cm", "program-execution", "perf-notes", "container-notes")
OUTSIDE = re.compile(r"\.\./shared|shared/spec|(?<![\w-])spec/[\w-]+\.md|(?<![\w/-])seeds/|"
                     r"(?<![\w#-])(?:%s)(?![\w-])|\bspec(?:'s)?\s+§" % "|".join(NOTES))

findings = []


def report(path, line_no, what, fix):
    findings.append(f"{path}:{line_no}: {what}; {fix}")


def check_md_name(path, line_no, token):
    """A Markdown file named in `path`: it must be in the repository."""
    if token.startswith("/"):   # "${PROJECT_SOURCE_DIR}/docs/ci.md": from the repository's root
        token = token.lstrip("/")
    base_dir = os.path.dirname(path)
    candidate = os.path.normpath(os.path.join(base_dir, token))
    if candidate.startswith(".."):
        report(path, line_no, f"'{token}' is outside the repository",
               "cite the project's own docs (docs/*.md) and name the source in words")
        return
    if os.path.isfile(os.path.join(ROOT, candidate)) or os.path.isfile(os.path.join(ROOT, token)):
        return
    if "/" not in token and (token in BASENAMES or os.path.isfile(os.path.join(ROOT, "docs", token))):
        return
    report(path, line_no, f"'{token}' is no file of the repository",
           "cite a docs/*.md page, and name a fact's source in words (e.g. \"SLMP Reference Manual, §5.2\")")


def scan(path, check_paths):
    try:
        text = open(os.path.join(ROOT, path), encoding="utf-8").read()
    except (UnicodeDecodeError, OSError):
        return
    for n, line in enumerate(text.splitlines(), 1):
        line = URL.sub(" ", line)
        if "signposts: allow" in line:   # the one escape hatch; say why on the same line
            continue
        m = OUTSIDE.search(line)
        if m:
            report(path, n, f"cites '{m.group(0)}', outside the repository",
                   "cite the project's own docs (docs/*.md) and name the source in words")
            continue
        for token in MD_NAME.findall(line):
            check_md_name(path, n, token)
        if not check_paths:
            continue
        for token in REPO_PATH.findall(line):
            if "node_modules/" in token:   # npm fills these (scripts/setup.sh); not part of a checkout
                continue
            if not exists(token):
                report(path, n, f"names '{token}', which does not exist", "point it at the file that holds it now")
        if line.lstrip().startswith("#include"):   # the compiler checks these
            continue
        for groups in BARE_SOURCE.findall(line):
            token = groups[0] or groups[1]
            if token in GENERATED:
                continue
            if token.endswith(".*"):
                stem = token[:-2]
                if not any(b.startswith(stem + ".") for b in BASENAMES):
                    report(path, n, f"names '{token}', which no folder holds", "point it at the file that holds it now")
            elif token not in BASENAMES:
                report(path, n, f"names '{token}', which no folder holds", "point it at the file that holds it now")


# In the map, a backticked path that does not start at a top-level folder
# ("`slmp/face.cpp`", "`capture/`") names a file only a reader who guesses
# its folder can find: the map writes every path from the repository's root.
RELATIVE_PATH = re.compile(r"`((?!(?:%s)/)[A-Za-z_][\w.-]*/(?:[\w./*{},-]*(?:\.[\w*}]+|/))?)`" % "|".join(TOP))


def check_map_paths():
    path = "docs/architecture.md"
    for n, line in enumerate(open(os.path.join(ROOT, path), encoding="utf-8").read().splitlines(), 1):
        for token in RELATIVE_PATH.findall(URL.sub(" ", line)):
            report(path, n, f"names '{token}', not a path from the repository's root",
                   "write it whole, from its top-level folder (e.g. 'frontends/slmp/face.cpp')")


def main():
    if "docs/architecture.md" not in FILES:
        print("check-architecture: docs/architecture.md is missing")
        return 1
    # 1 and 3 for the map; its bare names ("station_log.*") are checked like a comment's.
    scan("docs/architecture.md", check_paths=True)
    check_map_paths()
    for f in FILES:
        if f == "docs/architecture.md" or f.startswith("scripts/check-architecture"):
            continue
        if f.endswith(".md"):
            scan(f, check_paths=False)                                  # 3
        elif f.endswith(SOURCE_EXT) or os.path.basename(f) in SOURCE_NAMES:
            scan(f, check_paths=True)                                   # 2 and 3
    for line in findings:
        print(line)
    if findings:
        print(f"check-architecture: {len(findings)} signpost(s) point nowhere")
        return 1
    print(f"check-architecture: {len(FILES)} files, every signpost points at something there")
    return 0


if __name__ == "__main__":
    sys.exit(main())
