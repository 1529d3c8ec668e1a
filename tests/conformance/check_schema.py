"""docs/sidecar.schema.json against the conformance kit's sidecars: every
case's sidecar (the exporter's own metadata) must conform, and every bad
sidecar that is JSON and marked "schema_rejects" (the others break
cross-field rules JSON Schema cannot express: parent order, counts) must fail it at the field the kit names (a schema that accepts them
is too loose).

Implements the JSON Schema (2020-12) keywords the schema uses: type,
properties, required, additionalProperties, items, enum, const, minimum,
minItems, maxItems, pattern, $ref (to #/$defs/...). An unknown keyword in the
schema is an error, so the schema cannot silently use one this checker skips.

    /usr/bin/python3 check_schema.py SCHEMA KIT_DIR
"""
import json
import os
import re
import sys

from kit import Kit

KNOWN = {"$schema", "$id", "title", "description", "$defs", "type", "properties", "required",
         "additionalProperties", "items", "enum", "const", "minimum", "minItems", "maxItems",
         "pattern", "$ref"}
TYPES = {"object": dict, "array": list, "string": str, "boolean": bool}


def is_type(value, name):
    if name == "integer":
        return isinstance(value, int) and not isinstance(value, bool)
    if name == "number":
        return isinstance(value, (int, float)) and not isinstance(value, bool)
    if name == "null":
        return value is None
    return isinstance(value, TYPES[name])


def same(a, b):
    """JSON equality (true is not 1)."""
    return type(a) is type(b) and a == b or (is_type(a, "number") and is_type(b, "number") and a == b)


def validate(value, schema, root, where, errors):
    unknown = set(schema) - KNOWN
    if unknown:
        raise ValueError(f"schema keyword(s) {sorted(unknown)} at {where}: not implemented here")
    if "$ref" in schema:
        name = schema["$ref"].split("/")[-1]
        validate(value, root["$defs"][name], root, where, errors)
    if "type" in schema:
        types = schema["type"] if isinstance(schema["type"], list) else [schema["type"]]
        if not any(is_type(value, t) for t in types):
            errors.append(f"{where}: {json.dumps(value)[:40]} is not {'/'.join(types)}")
            return
    if "enum" in schema and not any(same(value, e) for e in schema["enum"]):
        errors.append(f"{where}: {json.dumps(value)[:40]} not one of {schema['enum']}")
    if "const" in schema and not same(value, schema["const"]):
        errors.append(f"{where}: {json.dumps(value)[:40]} is not {json.dumps(schema['const'])}")
    if "minimum" in schema and is_type(value, "number") and value < schema["minimum"]:
        errors.append(f"{where}: {value} < {schema['minimum']}")
    if "pattern" in schema and isinstance(value, str) and not re.search(schema["pattern"], value):
        errors.append(f"{where}: {value!r} does not match {schema['pattern']}")
    if isinstance(value, list):
        if len(value) < schema.get("minItems", 0):
            errors.append(f"{where}: {len(value)} items < {schema['minItems']}")
        if "maxItems" in schema and len(value) > schema["maxItems"]:
            errors.append(f"{where}: {len(value)} items > {schema['maxItems']}")
        if "items" in schema:
            for i, v in enumerate(value):
                validate(v, schema["items"], root, f"{where}[{i}]", errors)
    if isinstance(value, dict):
        for key in schema.get("required", []):
            if key not in value:
                errors.append(f"{where}: '{key}' missing")
        props = schema.get("properties", {})
        for key, v in value.items():
            if key in props:
                validate(v, props[key], root, f"{where}.{key}", errors)
            elif schema.get("additionalProperties", True) is False:
                errors.append(f"{where}: '{key}' not allowed")


def errors_of(value, schema):
    errors = []
    validate(value, schema, schema, "$", errors)
    return errors


def check_files(schema, paths):
    """Each sidecar file conforms: one line per problem, exit 1 on any."""
    failures = []
    for path in paths:
        with open(path, encoding="utf-8") as f:
            failures += [f"{path}: {e}" for e in errors_of(json.load(f), schema)[:5]]
    for f in failures:
        print(f)
    print(f"check_schema: {len(paths)} sidecars checked, {len(failures)} problems")
    return 1 if failures or not paths else 0


def main(argv):
    if len(argv) >= 2 and argv[1] == "--files":
        with open(argv[0], encoding="utf-8") as f:
            return check_files(json.load(f), argv[2:])
    if len(argv) != 2:
        print("usage: check_schema.py SCHEMA KIT_DIR | check_schema.py SCHEMA --files SIDECAR...",
              file=sys.stderr)
        return 2
    with open(argv[0], encoding="utf-8") as f:
        schema = json.load(f)
    kit = Kit(argv[1])
    failures, good, bad = [], 0, 0
    for entry, sidecar, _ in kit.cases():
        for e in errors_of(sidecar, schema)[:5]:
            failures.append(f"{os.path.join(kit.dir, entry['sidecar'])}: {e}")
        good += 1
    for entry, text in kit.bad():
        try:
            value = json.loads(text)
        except ValueError:
            continue  # not JSON: nothing for a schema to say
        if not entry["schema_rejects"]:
            continue  # a cross-field rule (parent order, counts): the runtimes check it
        named = [e for e in errors_of(value, schema) if entry["error"] == "json" or entry["error"] in e]
        if not named:
            failures.append(f"{entry['sidecar']}: the schema finds nothing wrong with "
                            f"'{entry['error']}' ({entry['what']})")
        bad += 1
    for f in failures:
        print(f)
    print(f"check_schema: {good} sidecars conform, {bad} bad sidecars checked, {len(failures)} problems")
    return 1 if failures or good == 0 else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
