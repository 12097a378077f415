#!/usr/bin/python3
"""Judges the --json lines of `twinraster render --backend both` run against one lavapipe on one CPU
path, for the scripts that prove a row of the twin's table outside the test suite
(check-aarch64.sh, check-mesa25-bookworm.sh). Every job must have been drawn by the driver and path
named (the driver's own driverInfo and device name say so), the twin must have chosen bit-exact
rules for that instruction set, and the images must not differ in one pixel. A job the driver
crashed on counts against --max-crashes (lavapipe's own bug at 128 bits, docs/mesa-128bit-crash.md).

Usage: check-twin-jobs.py RESULTS.jsonl --label NAME --jobs N --mesa 25.0.7 --llvm 15
                          --bits 256 --instruction-set AVX2+FMA [--max-crashes K]"""
import argparse
import json
import sys


def problems_of(job, a):
    """What is wrong with one job, or [] when it is a bit-exact comparison on the named driver."""
    gpu, rules = job["backends"]["gpu"], job["twin_rules"]
    if gpu["status"] != "rendered":
        return ["the GPU backend %s: %s" % (gpu["status"], gpu["problem"])]
    wrong = []
    if not (gpu["driver"] or "").startswith("Mesa " + a.mesa):
        wrong.append("driver %r is not Mesa %s" % (gpu["driver"], a.mesa))
    if "(LLVM %s." % a.llvm not in gpu["device"] or ", %d bits)" % a.bits not in gpu["device"]:
        wrong.append("device %r is not LLVM %s at %d bits" % (gpu["device"], a.llvm, a.bits))
    if rules is None or not rules["exact"] or rules["instruction_set"] != a.instruction_set:
        wrong.append("twin: %s" % (rules and rules["text"]))
    if job["differing_pixels"] != 0:
        wrong.append("%s differing pixels" % job["differing_pixels"])
    return wrong


def main():
    p = argparse.ArgumentParser()
    p.add_argument("results")
    p.add_argument("--label", required=True)
    p.add_argument("--jobs", type=int, required=True, help="how many jobs the run must have")
    p.add_argument("--mesa", required=True)
    p.add_argument("--llvm", required=True, help="LLVM's major version")
    p.add_argument("--bits", type=int, required=True)
    p.add_argument("--instruction-set", required=True)
    p.add_argument("--max-crashes", type=int, default=0)
    a = p.parse_args()
    jobs = [json.loads(line) for line in open(a.results) if line.strip()]
    exact = crashed = 0
    for job in jobs:
        name = job["scene"] + (" --wireframe" if job["wireframe"] else "")
        wrong = problems_of(job, a)
        if job["backends"]["gpu"]["status"] == "crashed":
            crashed += 1
            print("crashed %s" % name)
        elif wrong:
            print("FAIL    %s: %s" % (name, "; ".join(wrong)))
        else:
            exact += 1
    print("%s: %d of %d jobs bit-exact, %d crashed (at most %d allowed), %d expected"
          % (a.label, exact, len(jobs), crashed, a.max_crashes, a.jobs))
    names = [(job["scene"], job["wireframe"]) for job in jobs]
    if len(set(names)) != len(names):
        print("%s: a job appears twice" % a.label)
    ok = len(jobs) == a.jobs and len(set(names)) == len(names) and crashed <= a.max_crashes and exact + crashed == a.jobs
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
