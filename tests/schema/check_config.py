#!/usr/bin/env python3
"""Checks config/schema.json (generated from config/settings.cpp) against configuration files.

usage: check_config.py SCHEMA FILE...

- the schema must be a valid JSON Schema;
- every FILE must be valid against it;
- a file with a misspelt top-level key must not be.
Needs Debian's python3-jsonschema (scripts/setup.sh installs it).
"""
import json
import pathlib
import sys

try:
    import jsonschema
except ImportError:
    sys.exit("check_config.py: python3-jsonschema is missing; run scripts/setup.sh or apt-get install python3-jsonschema")


def main():
    schema = json.loads(pathlib.Path(sys.argv[1]).read_text())
    validator_class = jsonschema.validators.validator_for(schema)
    validator_class.check_schema(schema)
    validator = validator_class(schema)
    failures = []
    for name in sys.argv[2:]:
        for error in validator.iter_errors(json.loads(pathlib.Path(name).read_text())):
            failures.append("%s: /%s: %s" % (name, "/".join(map(str, error.path)), error.message))
    if validator.is_valid({"prfile": "R08CPU"}):
        failures.append("a misspelt key ('prfile') passes the schema")
    if validator.is_valid({"ports": [{"transport": "tcp", "port": 70000}]}):
        failures.append("port 70000 passes the schema")
    for failure in failures:
        print(failure)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
