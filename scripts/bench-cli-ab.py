#!/usr/bin/env python3
"""Interleaved whole-command timings (issue 19): runs the given commands in
turn, A B C ... A B C ..., RUNS times after one warm-up each, and prints the
median wall and CPU (user + sys, from wait4's rusage, as scripts/bench-cli.sh)
of each, with the load average before and after. On a shared machine the
interleaving puts every command under the same load.

    scripts/bench-cli-ab.py RUNS "CMD|ARG|ARG..." ["CMD|ARG..." ...]

Arguments of one command are separated by '|' (paths may hold spaces), e.g.
    B=/tmp/mozzi_bench_cli/hits_10x4x65536.uff
    scripts/bench-cli-ab.py 25 "$MAIN|uff|info|$B" "$MAIN|frf|$B|--estimator|H1" \\
        "$NEW|frf|$B|--estimator|H1" "$NEW|uff|info|$B"
"""
import os
import statistics
import subprocess
import sys
import time


def one(cmd):
    t0 = time.perf_counter()
    p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, _, ru = os.wait4(p.pid, 0)
    return (time.perf_counter() - t0) * 1e3, (ru.ru_utime + ru.ru_stime) * 1e3


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    runs = int(sys.argv[1])
    cmds = [c.split('|') for c in sys.argv[2:]]
    res = [[] for _ in cmds]
    for c in cmds:
        one(c)  # warm-up
    l0 = os.getloadavg()
    for _ in range(runs):
        for i, c in enumerate(cmds):
            res[i].append(one(c))
    l1 = os.getloadavg()
    print("load average %.2f %.2f %.2f -> %.2f %.2f %.2f" % (l0 + l1))
    for c, r in zip(cmds, res):
        wall = [x[0] for x in r]
        cpu = [x[1] for x in r]
        print("%-70s wall median %.1f ms (min %.1f), CPU median %.1f ms" %
              (' '.join(c)[-70:], statistics.median(wall), min(wall), statistics.median(cpu)))


if __name__ == "__main__":
    main()
