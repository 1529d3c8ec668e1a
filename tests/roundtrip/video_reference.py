#!/usr/bin/env python3
"""Writes the numpy reference of one video-layout case for the Blender round trip
(tests/roundtrip/blender_video.py): the case's expected posed vertices at its three clip frames
(tests/cli/layouts/video_cases.py expected(), the tool's conventions in numpy, never our C++) and
the rest mesh v_shaped of the clip's betas (to match Blender's vertices to the model's).

    /usr/bin/python3 video_reference.py --case wham_world --fixtures build/fixtures --out ref.json
"""
import argparse
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "cli", "layouts"))
import video_cases  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--case", required=True)
    ap.add_argument("--fixtures", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    case = next(c for c in video_cases.CASES if c["name"] == a.case)
    if case["outputs"] or case["refusal"]:
        sys.exit("%s: one output per case here (no --track all, no refusal)" % a.case)
    ref = video_cases.expected(case, a.fixtures)
    m = video_cases.load_model(a.fixtures, case["model"])
    (_, clip), = video_cases.clips(case, a.fixtures, m)
    ref["rest"] = video_cases.shaped(m, clip["betas"])[0].tolist()
    ref["case"] = a.case
    with open(a.out, "w", encoding="utf-8") as fh:
        json.dump(ref, fh)


if __name__ == "__main__":
    main()
