#!/usr/bin/env python3
"""Checks config/schema.json (generated from config/settings.cpp) against configuration files.

usage: check_config.py SCHEMA FILE...

- the schema must be a valid JSON Schema;
- every FILE must be valid against it;
- a file with a misspelt key must not be, at the top or in a nested object
  (the settings table's nested rows: networks, cpu.timers, limits...).
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
    nested_typos = [
        {"networks": [{"numbr": 1}]},
        {"modules": [{"start_io": "0030", "buffer_words": 16, "modle": "Q62DA"}]},
        {"cpus": [{"number": 2, "profile": "R08CPU", "devces": {}}]},
        {"drives": {"4": {"dri": "plc-data"}}},
        {"labels": [{"name": "a", "type": "Bit", "devce": "M0"}]},
        {"cpu": {"timers": [{"device": "T0", "preset": 1, "bse_ms": 100}]}},
        {"cpu": {"error": {"code": "1900", "stp": True}}},
        {"cpu": {"program": {"file": "a.csv", "wdt_ms": 205}}},
    ]
    for doc in nested_typos:
        if validator.is_valid(doc):
            failures.append("a nested mistake passes the schema: %s" % json.dumps(doc))
    for failure in failures:
        print(failure)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
