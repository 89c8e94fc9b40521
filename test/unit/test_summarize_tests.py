"""`make test` ends with one count over every JUnit file, and names each
failed case just before it, with the end of what it said (CI shows only
the end of the output)."""
import os
import subprocess
import sys

TOOL = os.path.join(os.path.dirname(__file__), '..', '..', 'tools', 'summarize_tests.py')
PYTEST_XML = '''<?xml version="1.0" encoding="utf-8"?><testsuites><testsuite name="pytest">
<testcase classname="test.class.test_grading" name="test_ok" time="1.0"/>
<testcase classname="test.class.test_grading" name="test_broken" time="2.0">
<failure message="assert 1 == 2">trace</failure></testcase>
<testcase classname="test.class.test_grading" name="test_later" time="0.0">
<skipped message="not root"/></testcase>
</testsuite></testsuites>'''
ROSTEST_XML = '''<?xml version="1.0" encoding="utf-8"?><testsuite name="rostest">
<testcase classname="turtle_letters.faults" name="test_3c" time="40.0">
<error type="" message="timed out"/></testcase>
<testcase classname="turtle_letters.rosunit-viewer" name="test_6" time="9.0">
<failure type="AssertionError"><![CDATA[Traceback (most recent call last):
  File "test_viewer.py", line 305, in test_6
    wait_until(lambda: ok(), 20, 'the page backing off')
AssertionError: waited 20 s for the page backing off, in vain
['live', 'live']
]]></failure></testcase>
<testcase classname="turtle_letters.faults" name="test_3d" time="4.0"/>
</testsuite>'''


def summarize(tmp_path, files):
    for name, text in files.items():
        path = tmp_path / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    done = subprocess.run([sys.executable, TOOL, str(tmp_path)],
                          stdout=subprocess.PIPE, universal_newlines=True, check=False)
    return done.returncode, done.stdout.splitlines()


def test_each_failure_and_error_is_named_with_its_last_words_before_the_count(tmp_path):
    code, lines = summarize(tmp_path, {'class/pytest.xml': PYTEST_XML,
                                       'turtle_letters/rostest-test_faults.xml': ROSTEST_XML})
    assert lines == [
        'FAILED class/pytest.xml: test.class.test_grading.test_broken',
        '    assert 1 == 2',
        'FAILED turtle_letters/rostest-test_faults.xml: turtle_letters.faults.test_3c',
        '    timed out',
        'FAILED turtle_letters/rostest-test_faults.xml: turtle_letters.rosunit-viewer.test_6',
        "    wait_until(lambda: ok(), 20, 'the page backing off')",
        '    AssertionError: waited 20 s for the page backing off, in vain',
        "    ['live', 'live']",
        '2 passed, 3 failed, 1 skipped']
    assert code == 1


def test_all_passed_is_one_line_and_exit_0(tmp_path):
    code, lines = summarize(tmp_path, {'unit/pytest.xml': PYTEST_XML.replace(
        '<failure message="assert 1 == 2">trace</failure>', '')})
    assert (code, lines) == (0, ['2 passed, 0 failed, 1 skipped'])


def test_an_unreadable_file_counts_as_a_failure(tmp_path):
    code, lines = summarize(tmp_path, {'network/pytest.xml': '<testsuite><testcase'})
    assert (code, lines) == (1, ['FAILED network/pytest.xml: unreadable test result',
                                 '0 passed, 1 failed'])


def test_no_results_at_all_is_a_failure(tmp_path):
    code, lines = summarize(tmp_path, {})
    assert (code, lines) == (1, ['0 passed, 0 failed'])
