#!/usr/bin/python3
"""The JSON Schema of `shadetree schema` (graph/format_schema.h) against a
real validator (Debian's python3-jsonschema, draft 2020-12): it accepts
every gallery graph and every example in docs/graph-format.md, and refuses
the broken files that `shadetree check` refuses.

Usage: format_schema_test.py SHADETREE SOURCE_DIR
"""
import glob
import json
import os
import re
import subprocess
import sys
import tempfile

import jsonschema

shadetree, source = sys.argv[1], sys.argv[2]
schema = json.loads(subprocess.run([shadetree, "schema"], check=True, capture_output=True, text=True).stdout)
jsonschema.Draft202012Validator.check_schema(schema)
validator = jsonschema.Draft202012Validator(schema)
passed = failed = 0


def expect(ok, what):
    global passed, failed
    if ok:
        passed += 1
    else:
        failed += 1
        print("FAIL:", what)


def problems(document):
    return [f"{'/'.join(map(str, e.absolute_path))}: {e.message[:160]}" for e in validator.iter_errors(document)]


def minimal_graph(kind, **fields):
    graph = {"format": "shadetree-graph", "version": 1, "kind": kind,
             "nodes": [{"id": "d", "op": "P"}], "outputs": {"density" if kind == "volume" else "color": 0.5}}
    if kind == "volume":  # a volume is rendered only within its bounds
        graph["render"] = {"volume": {"bounds": {"min": [0, 0, 0], "max": [1, 1, 1]}}}
    graph.update(fields)
    return graph


# Every gallery graph.
for path in sorted(glob.glob(os.path.join(source, "graphs", "*.json"))):
    with open(path) as file:
        found = problems(json.load(file))
    expect(not found, f"{os.path.basename(path)} is refused: {found[:2]}")

# Every example of docs/graph-format.md: whole graphs, nodes, and render
# sections (validated inside a graph of the kind they are for).
with open(os.path.join(source, "docs", "graph-format.md")) as file:
    blocks = re.findall(r"```json\n(.*?)```", file.read(), re.S)
node_schema = dict(schema["$defs"]["node"], **{"$defs": schema["$defs"]})
for block in blocks:
    if block.lstrip().startswith('"render"'):
        render = json.loads("{" + block + "}")["render"]
        kind = "volume" if "volume" in render else "surface" if "scene" in render else "texture"
        found = problems(minimal_graph(kind, render=render))
    else:
        example = json.loads(block)
        if "format" in example:
            found = problems(example)
        else:
            found = [e.message for e in jsonschema.Draft202012Validator(node_schema).iter_errors(example)]
    expect(not found, f"docs example {block[:60]!r} is refused: {found[:2]}")

# Broken files: refused by check (exit status 2) and by the schema.
broken = {
    "unknown_field": minimal_graph("texture", colour="red"),
    "volume_in_a_surface": minimal_graph("surface", render={"volume": {"bounds": {"min": [0, 0, 0], "max": [1, 1, 1]}}}),
    "scene_in_a_texture": minimal_graph("texture", render={"scene": {"objects": [{"type": "sphere"}]}}),
    "coloured_surface_object": minimal_graph("surface", render={"scene": {"objects": [{"type": "plane", "color": 1}]}}),
    "surface_scene_without_objects": minimal_graph("surface", render={"scene": {"background": 0.5}}),
    "unknown_object_type": minimal_graph("surface", render={"scene": {"objects": [{"type": "cone"}]}}),
    "radius_on_a_box": minimal_graph("surface", render={"scene": {"objects": [{"type": "box", "radius": 1}]}}),
    "point_light_with_direction": minimal_graph(
        "surface", render={"scene": {"objects": [{"type": "sphere"}],
                                     "lights": [{"type": "point", "direction": [0, 1, 0]}]}}),
    "bounds_without_max": minimal_graph("volume", render={"volume": {"bounds": {"min": [0, 0, 0]}}}),
    "unknown_volume_field": minimal_graph("volume", render={"volume": {"bounds": {"min": [0, 0, 0], "max": [1, 1, 1]},
                                                                       "stepsize": 1}}),
    "param_without_default": minimal_graph("texture", params={"s": {"type": "float"}}),
    "unknown_kind": minimal_graph("hologram"),
    "volume_without_bounds": minimal_graph("volume", render={"size": [8, 8]}),
    "volume_without_render": {key: value for key, value in minimal_graph("volume").items() if key != "render"},
    "no_nodes": {"format": "shadetree-graph", "version": 1, "kind": "texture", "outputs": {"color": 1}},
    "version_2": minimal_graph("texture", version=2),
}
with tempfile.TemporaryDirectory() as folder:
    # The graph each broken file spoils is itself valid, for each kind.
    for kind in ("texture", "surface", "volume"):
        path = os.path.join(folder, kind + ".json")
        with open(path, "w") as file:
            json.dump(minimal_graph(kind), file)
        check = subprocess.run([shadetree, "check", path], capture_output=True, text=True)
        expect(check.returncode == 0, f"check refuses the minimal {kind} graph: {check.stderr}")
        expect(not problems(minimal_graph(kind)), f"the schema refuses the minimal {kind} graph")
    for name, document in broken.items():
        path = os.path.join(folder, name + ".json")
        with open(path, "w") as file:
            json.dump(document, file)
        check = subprocess.run([shadetree, "check", path], capture_output=True, text=True)
        expect(check.returncode == 2, f"check accepts {name} (status {check.returncode}): {check.stdout}")
        expect(problems(document), f"the schema accepts {name}")

print(f"{passed} passed, {failed} failed")
sys.exit(1 if failed else 0)
