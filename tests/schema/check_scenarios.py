#!/usr/bin/env python3
"""Checks scenarios/schema.json against the files it describes.

usage: check_scenarios.py SCHEMA EXAMPLES_DIR MISTAKES_JSON [SCENARIO.json ...]

- every *.json in EXAMPLES_DIR must be valid, and every SCENARIO.json named
  after the three (scenarios a tool writes: slmp-replay --to-scenario's
  tests/data/hmi_session.scenario.json);
- every mistake in MISTAKES_JSON marked "schema": true must be invalid (the
  others are caught by the C++ loader only; the unit tests check its messages).
Needs Debian's python3-jsonschema (scripts/setup.sh installs it).
"""
import json
import pathlib
import sys

try:
    import jsonschema
except ImportError:
    sys.exit("check_scenarios.py: python3-jsonschema is missing; run scripts/setup.sh or apt-get install python3-jsonschema")


def main():
    schema_path, examples_dir, mistakes_path = map(pathlib.Path, sys.argv[1:4])
    schema = json.loads(schema_path.read_text())
    validator_class = jsonschema.validators.validator_for(schema)
    validator_class.check_schema(schema)
    validator = validator_class(schema)
    failures = []

    examples = sorted(examples_dir.glob("*.json"))
    if len(examples) < 6:
        failures.append(f"expected at least 6 examples in {examples_dir}, found {len(examples)}")
    for path in examples + [pathlib.Path(p) for p in sys.argv[4:]]:
        errors = sorted(validator.iter_errors(json.loads(path.read_text())), key=lambda e: list(e.absolute_path))
        for e in errors:
            pointer = "/" + "/".join(str(p) for p in e.absolute_path)
            failures.append(f"{path.name}: {pointer}: {e.message}")

    mistakes = json.loads(mistakes_path.read_text())
    checked = 0
    for m in mistakes:
        if not m.get("schema"):
            continue
        checked += 1
        if validator.is_valid(m["doc"]):
            failures.append(f"schema accepts a mistake it should reject: {m['what']}: {json.dumps(m['doc'])}")

    for f in failures:
        print(f, file=sys.stderr)
    print(f"{len(examples)} example(s) valid, {checked} mistake(s) rejected" if not failures else f"{len(failures)} problem(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
