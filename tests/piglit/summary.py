#!/usr/bin/env python3
"""Summarizes tests/piglit/run.sh's piglit runs: result counts of llvmpipe and shadelab side by
side, the tests whose results differ, and with --require-pass the check of the CI list (its
closing line 'N passed, M failed'; exit status 1 unless every listed test passed)."""
import argparse
import bz2
import collections
import glob
import gzip
import json
import os
import re
import sys
import xml.etree.ElementTree as ET

RESULTS = ["pass", "fail", "warn", "skip", "crash", "timeout", "incomplete", "notrun"]


def load(folder):
    """The per-test results of one piglit run, by test name ({} if it did not run)."""
    for name, opener in (("results.json.bz2", bz2.open), ("results.json.gz", gzip.open), ("results.json", open)):
        path = os.path.join(folder, name)
        if os.path.exists(path):
            with opener(path, "rt") as f:
                return {n: v["result"] for n, v in json.load(f)["tests"].items()}
    return {}


def groups_left_out(minor):
    """Tests of quick_gl's !opengl 1.x groups above the reported version (not run)."""
    profiles = glob.glob("/usr/lib/*/piglit/tests/quick_gl.xml.gz") + glob.glob("/usr/lib/piglit/tests/quick_gl.xml.gz")
    if not profiles:
        return None
    pattern = re.compile(r"spec@!opengl 1\.([0-9])@")
    count = 0
    for test in ET.parse(gzip.open(profiles[0])).getroot():
        m = pattern.match(test.get("name", ""))
        if m and int(m.group(1)) > minor:
            count += 1
    return count


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--out", required=True)
    p.add_argument("--version", required=True)
    p.add_argument("--up-to", required=True)
    p.add_argument("--shadelab-only", action="store_true")
    p.add_argument("--require-pass")
    a = p.parse_args()
    shadelab = load(os.path.join(a.out, "shadelab"))
    llvmpipe = {} if a.shadelab_only else load(os.path.join(a.out, "llvmpipe"))
    if not shadelab:
        print(f"summary: no piglit results in {a.out}/shadelab (see {a.out}/shadelab.log)")
        return 1
    minor = int(a.up_to.split(".")[1])
    names = sorted(set(shadelab) | set(llvmpipe))
    print(f"piglit quick_gl, spec@!opengl 1.0 to 1.{minor} (shadelab reports OpenGL {a.version}), "
          f"no GLSL: {len(names)} tests")
    left_out = groups_left_out(minor)
    if left_out and not a.require_pass:
        print(f"not run: {left_out} tests of the groups !opengl 1.{minor + 1} to 1.5")
    count_s = collections.Counter(shadelab.values())
    count_l = collections.Counter(llvmpipe.values())
    print(f"{'result':<12}{'llvmpipe':>10}{'shadelab':>10}")
    for r in RESULTS:
        if count_s[r] or count_l[r]:
            print(f"{r:<12}{(count_l[r] if llvmpipe else '-'):>10}{count_s[r]:>10}")
    bad = [n for n in names if shadelab.get(n) in ("crash", "timeout", "incomplete")]
    print(f"crashes, timeouts, incomplete on shadelab: {len(bad)}")
    for n in bad:
        print(f"  {n}: {shadelab[n]}")
    if llvmpipe:
        lost = [n for n in names if llvmpipe.get(n) == "pass" and shadelab.get(n) != "pass"]
        differ = [n for n in names if llvmpipe.get(n) != shadelab.get(n)]
        print(f"pass on llvmpipe, not on shadelab: {len(lost)}")
        print(f"tests whose results differ (llvmpipe -> shadelab): {len(differ)}")
        for n in differ:
            print(f"  {n}: {llvmpipe.get(n, 'absent')} -> {shadelab.get(n, 'absent')}")
    if a.require_pass:
        with open(a.require_pass) as f:
            wanted = [line.split("#")[0].strip() for line in f]
        wanted = [w for w in wanted if w]
        failed = [w for w in wanted if shadelab.get(w) != "pass"]
        for w in failed:
            print(f"FAIL {w}: {shadelab.get(w, 'not run')}")
        print(f"{len(wanted) - len(failed)} passed, {len(failed)} failed")
        return 1 if failed else 0
    return 0


if __name__ == "__main__":
    sys.exit(main())
