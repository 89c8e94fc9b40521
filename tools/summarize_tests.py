"""Count the test cases in JUnit XML files and print one line: N passed, N failed[, N skipped].

Each failed case is named on a line of its own just before it, with the end
of what it said: CI shows only the end of the output, and the count alone
does not say which test to read, nor a failure seen once in CI why it failed.
"""
import glob
import os
import sys
import xml.etree.ElementTree as ET

SAID_LINES, SAID_WIDTH = 3, 200     # how much of a failure's own words is shown


def outcome(case):
    kinds = {child.tag for child in case}
    if kinds & {'failure', 'error'}:
        return 'failed'
    return 'skipped' if 'skipped' in kinds else 'passed'


def said(case):
    """The last few lines a failed case said: pytest's short message, or the
    end of a traceback (rosunit keeps only that), each cut to SAID_WIDTH."""
    for child in case:
        if child.tag in ('failure', 'error'):
            text = child.get('message') or child.text or ''
            lines = [line.strip() for line in text.splitlines() if line.strip()]
            return [line[:SAID_WIDTH] for line in lines[-SAID_LINES:]]
    return []


def case_name(results_dir, path, case):
    where = os.path.relpath(path, results_dir)
    return f"{where}: {case.get('classname', '')}.{case.get('name', '')}"


def main(results_dir):
    counts = {'passed': 0, 'failed': 0, 'skipped': 0}
    failures = []
    for path in sorted(glob.glob(os.path.join(results_dir, '**', '*.xml'), recursive=True)):
        try:
            root = ET.parse(path).getroot()
        except ET.ParseError:
            failures.append((f'{os.path.relpath(path, results_dir)}: unreadable test result', []))
            counts['failed'] += 1
            continue
        for case in root.iter('testcase'):
            kind = outcome(case)
            counts[kind] += 1
            if kind == 'failed':
                failures.append((case_name(results_dir, path, case), said(case)))
    for name, words in failures:
        print(f'FAILED {name}')
        for line in words:
            print(f'    {line}')
    line = f"{counts['passed']} passed, {counts['failed']} failed"
    print(line + (f", {counts['skipped']} skipped" if counts['skipped'] else ''))
    return 1 if counts['failed'] or counts['passed'] == 0 else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1]))
