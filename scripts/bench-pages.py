#!/usr/bin/python3
"""Times how the 1,000-scene batch report opens in headless Chromium. It renders the same report as
tests/pages/check_pages.py's "thousand" case (1,000 copies of cgfs-transforms at 64 x 64, both
backends) and opens it --runs times, each in a fresh browser. It prints the size of index.html
and the median, min and max of two times: (a) until driver.get() returns, which is when the page
has loaded with the thumbnails in view; (b) from navigation start to the end of the load event
(performance.timing). This is a benchmark, not a test: the times depend on the machine and on what
else runs on it, which is why the test no longer judges them.

Usage: /usr/bin/python3 scripts/bench-pages.py --exe build/bin/twinraster [--runs N] [--work DIR]
--work keeps the scenes and the report in DIR; without it they go to a temporary directory that is
removed at the end."""
import argparse
import os
import shutil
import statistics
import sys
import tempfile

SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(SOURCE, "tests", "pages"))
sys.dont_write_bytecode = True  # no __pycache__ left in the source tree by the import below
import check_pages  # noqa: E402  (found through the path above)


def measure(page, runs):
    """Opens the page `runs` times, each in a new browser, so no run reuses another's cache."""
    seconds, load_ms = [], []
    for _ in range(runs):
        driver = check_pages.browser()
        try:
            s, ms = check_pages.open_timed(driver, page)
        finally:
            driver.quit()
        seconds.append(s)
        load_ms.append(ms)
    return seconds, load_ms


def table(rows):
    """Prints rows of (label, median, min, max) strings with the numbers right-aligned."""
    width = max(len(r[0]) for r in rows)
    for label, *numbers in rows:
        print(label.ljust(width) + "".join(n.rjust(10) for n in numbers))


def bench(a, work):
    lines, page, _, render_seconds = check_pages.render_thousand(a, work)
    size = os.path.getsize(page)
    seconds, load_ms = measure(page, a.runs)
    print("index.html: %s bytes, %d scenes (rendered in %.1f s)" % (format(size, ","), len(lines), render_seconds))
    table([("%d runs, a fresh headless Chromium each" % a.runs, "median", "min", "max"),
           ("driver.get() returned (s)", *("%.2f" % f(seconds) for f in (statistics.median, min, max))),
           ("load event end (ms)", *("%.0f" % f(load_ms) for f in (statistics.median, min, max)))])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--exe", required=True, help="the twinraster executable")
    parser.add_argument("--runs", type=int, default=5, help="times to open the page (default 5)")
    parser.add_argument("--work", help="keep the scenes and the report in this directory")
    a = parser.parse_args()
    if a.runs < 1:
        parser.error("--runs must be at least 1")
    a.exe = os.path.abspath(a.exe)
    a.source = SOURCE
    if a.work:
        os.makedirs(a.work, exist_ok=True)
        bench(a, a.work)
        return
    work = tempfile.mkdtemp(prefix="bench-pages-")
    try:
        bench(a, work)
    finally:
        shutil.rmtree(work)


if __name__ == "__main__":
    main()
