#!/usr/bin/env python3
"""Checks the CI examples (examples/ci/*.yml): each parses as YAML, and every
slmp-sim option it names is one `slmp-sim --help` lists, every HTTP endpoint
it calls is one docs/api.md documents. Exit 77 (CTest: skipped) without
python3-yaml.

Usage: check_ci_examples.py SLMP_SIM_BINARY EXAMPLES_DIR DOCS_CI_MD
"""
import pathlib
import re
import shlex
import subprocess
import sys

try:
    import yaml
except ImportError:
    print("SKIPPED: python3-yaml is not installed (apt-get install python3-yaml, or run scripts/setup.sh)")
    sys.exit(77)

binary, examples, ci_md = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
api_md = (ci_md.parent / "api.md").read_text()
help_text = subprocess.run([binary, "--help"], capture_output=True, text=True, check=True).stdout
known = set(re.findall(r"--[a-z][a-z-]+", help_text))
# The endpoints docs/api.md documents, as patterns: {name} matches one segment.
documented = set()
for path in re.findall(r"(?:GET|PUT|POST|DELETE) (/api/[A-Za-z0-9_/{}.-]*)", api_md):
    documented.add(re.compile("^" + re.sub(r"\{[^}]+\}", "[^/]+", path.rstrip("/")) + "$"))

failures = []


def strings(node):
    if isinstance(node, dict):
        for value in node.values():
            yield from strings(value)
    elif isinstance(node, list):
        yield node
        for value in node:
            yield from strings(value)
    elif isinstance(node, str):
        yield node


def options_after_slmp_sim(text):
    """The --options of every `slmp-sim ...` command line in a shell text, and of `docker run ... slmp-sim ...`."""
    found = []
    for line in text.replace("\\\n", " ").splitlines():
        for part in re.split(r"&&|\|\||;|\|", line):
            try:
                words = shlex.split(part, comments=True)
            except ValueError:
                words = part.split()
            for i, word in enumerate(words):
                if word.endswith("slmp-sim") and not word.startswith("-"):
                    found += [w.split("=")[0] for w in words[i + 1:] if w.startswith("--")]
                    break
    return found


def service_commands(doc):
    """command: lists of services whose image or build is slmp-sim (compose, GitLab services)."""
    out = []
    def visit(node):
        if isinstance(node, dict):
            image = str(node.get("image", node.get("name", "")))
            built = isinstance(node.get("build"), dict) and "dockerfile" in node["build"]
            if ("slmp-sim" in image or "SLMP_SIM_IMAGE" in image or built) and isinstance(node.get("command"), list):
                out.extend(w for w in node["command"] if isinstance(w, str) and w.startswith("--"))
            for value in node.values():
                visit(value)
        elif isinstance(node, list):
            for value in node:
                visit(value)
    visit(doc)
    return out


files = sorted(examples.glob("*.yml"))
if not files:
    failures.append("no YAML files in %s" % examples)
for f in files:
    try:
        doc = yaml.safe_load(f.read_text())
    except yaml.YAMLError as e:
        failures.append("%s: not valid YAML: %s" % (f.name, e))
        continue
    named = service_commands(doc)
    endpoints = []
    for s in strings(doc):
        if isinstance(s, str):
            named += options_after_slmp_sim(s)
            endpoints += re.findall(r"(?:https?://)?[A-Za-z0-9_.-]+:[0-9]+(/api/[A-Za-z0-9_/.-]*)", s)
    if not named:
        failures.append("%s: names no slmp-sim option; is it still an slmp-sim example?" % f.name)
    for option in named:
        if option not in known:
            failures.append("%s: slmp-sim has no option %s (see slmp-sim --help)" % (f.name, option))
    for path in endpoints:
        if not any(p.match(path.rstrip("/")) for p in documented):
            failures.append("%s: endpoint %s is not in docs/api.md" % (f.name, path))
    print("%s: %d slmp-sim option(s), %d endpoint(s) checked" % (f.name, len(named), len(endpoints)))

if str(examples.name) not in ci_md.read_text() and "examples/ci" not in ci_md.read_text():
    failures.append("docs/ci.md does not point at examples/ci")
for failure in failures:
    print("FAIL: " + failure)
sys.exit(1 if failures else 0)
