"""Count the test cases in JUnit XML files and print one line: N passed, N failed[, N skipped]."""
import glob
import os
import sys
import xml.etree.ElementTree as ET


def main(results_dir):
    passed = failed = skipped = 0
    for path in glob.glob(os.path.join(results_dir, '**', '*.xml'), recursive=True):
        try:
            root = ET.parse(path).getroot()
        except ET.ParseError:
            print(f'unreadable test result {path}', file=sys.stderr)
            failed += 1
            continue
        for case in root.iter('testcase'):
            kinds = {child.tag for child in case}
            if kinds & {'failure', 'error'}:
                failed += 1
            elif 'skipped' in kinds:
                skipped += 1
            else:
                passed += 1
    line = f'{passed} passed, {failed} failed'
    print(line + (f', {skipped} skipped' if skipped else ''))
    return 1 if failed or passed == 0 else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1]))
