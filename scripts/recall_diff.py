#!/usr/bin/env python3
"""Which warnings and errors one asset-lint binary reports that another no longer does.

Usage:
  scripts/recall_diff.py OLD_BINARY NEW_BINARY PATH_OR_LIST... [--json OUT]

Each argument after the two binaries is a file or directory to check, or a text file ending in
`list.txt` that names one asset per line (the layout of the fresh review sets). Both binaries
check the same paths in the same working directory (`--output-format json --exit-zero`), and the
warnings and errors are compared by file, rule and message (line numbers are left out, so an
edit that only moves a finding does not count; a reworded message of the same rule on the same
file stands for one old finding, not for all of them). Printed:

  lost      a warning or error of OLD that NEW does not report at all
  demoted   reported by NEW at a lower severity (a warning or error that became an info, an
            error that became a warning)
  new       a warning or error of NEW that OLD did not report

Every lost or demoted finding needs a one-line justification in docs/corpus-review.md before
the change lands. Exit status: 0 when nothing was lost or demoted, 1 otherwise, 2 on a usage
or run error.
"""
import argparse
import collections
import json
import pathlib
import subprocess
import sys

RANK = {"info": 0, "warning": 1, "error": 2}


def expand(paths):
    out = []
    for p in paths:
        path = pathlib.Path(p)
        if path.name.endswith("list.txt") and path.is_file():
            out.extend(line.strip() for line in path.read_text().splitlines() if line.strip())
        else:
            out.append(p)
    return out


def findings(binary, paths):
    """Every finding of BINARY over PATHS, keyed by (file, rule, message) with its severity."""
    done = subprocess.run([binary, "--output-format", "json", "--exit-zero", *paths],
                          capture_output=True, text=True)
    try:
        report = json.loads(done.stdout)
    except json.JSONDecodeError:
        sys.exit(f"{binary} printed no JSON (exit {done.returncode}): {done.stderr.strip()[:400]}")
    result = collections.defaultdict(list)
    for d in report["diagnostics"]:
        result[(d["file"], d["rule"], d["message"])].append(d["severity"])
    return result


def by_file_and_rule(found):
    out = collections.defaultdict(list)
    for (file, rule, message), severities in found.items():
        out[(file, rule)].append((message, max(severities, key=RANK.get)))
    return out


def compare(old, new):
    lost, demoted, added = [], [], []
    new_by_rule = by_file_and_rule(new)
    used = set()  # reworded messages already matched to an old one: each stands for one finding
    for key, severities in sorted(old.items()):
        worst = max(severities, key=RANK.get)
        if RANK[worst] < RANK["warning"]:
            continue
        if key in new:
            now = max(new[key], key=RANK.get)
            if RANK[now] < RANK[worst]:
                demoted.append((key, worst, now))
            continue
        file, rule, _ = key
        # The same rule on the same file with a reworded message and no lower severity is not a loss.
        rivals = [(m, s) for m, s in new_by_rule.get((file, rule), [])
                  if (file, rule, m) not in old and (file, rule, m) not in used and RANK[s] >= RANK[worst]]
        if rivals:
            used.add((file, rule, rivals[0][0]))
            continue
        lower = [(m, s) for m, s in new_by_rule.get((file, rule), [])
                 if (file, rule, m) not in old and (file, rule, m) not in used]
        if lower:
            used.add((file, rule, lower[0][0]))
            demoted.append((key, worst, lower[0][1]))
        else:
            lost.append((key, worst))
    for key, severities in sorted(new.items()):
        worst = max(severities, key=RANK.get)
        if RANK[worst] >= RANK["warning"] and key not in old:
            added.append((key, worst))
    return lost, demoted, added


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("old")
    parser.add_argument("new")
    parser.add_argument("paths", nargs="+")
    parser.add_argument("--json", help="also write the three lists to this file")
    args = parser.parse_args()
    paths = expand(args.paths)
    old, new = findings(args.old, paths), findings(args.new, paths)
    lost, demoted, added = compare(old, new)
    for (file, rule, message), was in lost:
        print(f"lost     {was:7} {file} [{rule}] {message}")
    for (file, rule, message), was, now in demoted:
        print(f"demoted  {was}->{now} {file} [{rule}] {message}")
    for (file, rule, message), now in added:
        print(f"new      {now:7} {file} [{rule}] {message}")
    print(f"{len(lost)} lost, {len(demoted)} demoted, {len(added)} new "
          f"(warnings and errors of {len(paths)} paths)")
    if args.json:
        pathlib.Path(args.json).write_text(json.dumps(
            {"lost": [list(k) + [w] for k, w in lost],
             "demoted": [list(k) + [w, n] for k, w, n in demoted],
             "new": [list(k) + [n] for k, n in added]}, indent=1, ensure_ascii=False))
    return 1 if lost or demoted else 0


if __name__ == "__main__":
    sys.exit(main())
