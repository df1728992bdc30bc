#!/usr/bin/env python3
"""Count asset-lint's findings per rule and severity over the shared corpus.

Usage (from the repository root, after a build):
  scripts/corpus_review.py --record-before   # store today's counts as the "before" column
  scripts/corpus_review.py                   # rewrite the table in docs/corpus-review.md (before/after)
  scripts/corpus_review.py --sample 8        # print a sample of N findings per rule, for reading

The corpus is ../shared/corpus (override with --corpus), checked in one run from inside it
(`asset-lint --output-format json .`): URDF, USDA and every other format the build reads.
"""
import argparse
import collections
import json
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
TABLE_START = "<!-- corpus-review:start (written by scripts/corpus_review.py) -->"
TABLE_END = "<!-- corpus-review:end -->"
BEFORE_FILE = ROOT / "docs" / "corpus-review-before.json"
SEVERITIES = ("error", "warning", "info")


def run_corpus(binary, corpus):
    """Every finding of one run over the whole corpus, as a new user would start it."""
    done = subprocess.run([str(binary), "--output-format", "json", "."], capture_output=True, text=True, cwd=corpus)
    try:
        return json.loads(done.stdout)["diagnostics"]
    except json.JSONDecodeError:
        sys.exit(f"asset-lint printed no JSON for {corpus} (exit {done.returncode}): {done.stderr.strip()}")


def count(diagnostics):
    per_rule = collections.defaultdict(lambda: collections.Counter())
    for d in diagnostics:
        per_rule[d["rule"]][d["severity"]] += 1
    files = len({d["file"] for d in diagnostics})
    return {"rules": {rule: dict(c) for rule, c in per_rule.items()},
            "total": len(diagnostics), "files": files}


def cell(counts):
    if not counts:
        return "0"
    parts = [f"{counts[s]} {s}" for s in SEVERITIES if counts.get(s)]
    return " · ".join(parts)


def table(before, after):
    rules = sorted(set(before["rules"]) | set(after["rules"]))
    lines = ["| rule | before | after |", "|---|---|---|"]
    for rule in rules:
        lines.append(f"| {rule} | {cell(before['rules'].get(rule))} | {cell(after['rules'].get(rule))} |")

    def totals(c):
        by_sev = collections.Counter()
        for counts in c["rules"].values():
            by_sev.update(counts)
        return f"{c['total']} in {c['files']} files ({cell(by_sev)})"

    lines.append(f"| **all** | {totals(before)} | {totals(after)} |")
    return "\n".join(lines)


def write_table(text):
    rules_md = ROOT / "docs" / "corpus-review.md"
    content = rules_md.read_text()
    block = f"{TABLE_START}\n{text}\n{TABLE_END}"
    if TABLE_START in content:
        head, rest = content.split(TABLE_START, 1)
        tail = rest.split(TABLE_END, 1)[1]
        content = head + block + tail
    else:
        content = content.rstrip("\n") + "\n\n" + block + "\n"
    rules_md.write_text(content)


def sample(diagnostics, per_rule):
    """Up to `per_rule` findings per rule, spread over as many files as possible."""
    by_rule = collections.defaultdict(list)
    for d in diagnostics:
        by_rule[d["rule"]].append(d)
    out = []
    for rule in sorted(by_rule):
        chosen, seen_files = [], set()
        for d in by_rule[rule]:  # one per file first, then fill up
            if d["file"] not in seen_files and len(chosen) < per_rule:
                chosen.append(d)
                seen_files.add(d["file"])
        for d in by_rule[rule]:
            if len(chosen) >= per_rule:
                break
            if d not in chosen:
                chosen.append(d)
        out.append((rule, len(by_rule[rule]), chosen))
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--binary", default=str(ROOT / "build" / "asset-lint"))
    parser.add_argument("--corpus", default=str(ROOT.parent / "shared" / "corpus"))
    parser.add_argument("--record-before", action="store_true", help="store the counts as the 'before' column")
    parser.add_argument("--sample", type=int, metavar="N", help="print N findings per rule instead of the table")
    args = parser.parse_args()

    corpus = pathlib.Path(args.corpus).resolve()
    if not corpus.is_dir():
        sys.exit(f"no corpus at {corpus}")
    diagnostics = run_corpus(pathlib.Path(args.binary).resolve(), corpus)

    if args.sample:
        for rule, total, chosen in sample(diagnostics, args.sample):
            print(f"\n### {rule} ({total} findings)\n")
            for d in chosen:
                path = pathlib.Path(d["file"]).name
                print(f"- `{path}:{d['line']}` {d['severity']}: {d['message']}")
        return

    counts = count(diagnostics)
    if args.record_before:
        BEFORE_FILE.write_text(json.dumps(counts, indent=2, sort_keys=True) + "\n")
        print(f"recorded {counts['total']} findings in {counts['files']} files as 'before'")
        return
    before = json.loads(BEFORE_FILE.read_text()) if BEFORE_FILE.exists() else {"rules": {}, "total": 0, "files": 0}
    write_table(table(before, counts))
    print(table(before, counts))


if __name__ == "__main__":
    main()
