#!/usr/bin/python3
"""Each node, started with a bad parameter, says so in one fatal line that
names the parameter and what is allowed, and exits 2: no traceback, nothing
started. The nodes run for real against the test's master."""
import os
import subprocess
import unittest

import rostest

DOC = os.path.join(os.path.dirname(os.path.realpath(__file__)), '..', 'doc')
FLOWER = os.path.realpath(os.path.join(DOC, 'flower.svg'))
NOT_A_FOLDER = os.path.realpath(__file__)

CASES = [
    ('grade.py', ['_settle:=soon'], "~settle is 'soon'; allowed: a number > 0 (s)"),
    ('grade.py', ['_timeout:=-1'], '~timeout is -1; allowed: a number > 0 (s)'),
    ('grade.py', ['_tolerance:=.nan'], '~tolerance is nan; allowed: a number > 0 (m)'),
    ('scoreboard.py', ['_tolerance:=wide'], "~tolerance is 'wide'; allowed: a number > 0 (m)"),
    ('grade.py', [f'_out:={NOT_A_FOLDER}/grades'],            # under a file
     f"~out is '{NOT_A_FOLDER}/grades'; allowed: a folder this node can create or write in"),
    ('scoreboard.py', ['_out:=5'], '~out is 5; allowed: the path of a folder'),
    ('turtle_controller.py', ['_text:=HI', f'_svg:={FLOWER}'],
     "~text is 'HI' and ~svg is"),
]


def run(number, node, params):
    """The node's output and exit status (a name of its own: private
    parameters stay on the master); output unbuffered, so that nothing
    depends on the caller's environment."""
    name = f'__name:=bad_{number}'
    done = subprocess.run(['rosrun', 'turtle_letters', node, name] + params,
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=60,
                          env=dict(os.environ, PYTHONUNBUFFERED='1'))
    return done.stdout.decode(errors='replace'), done.returncode


class BadParameters(unittest.TestCase):
    def test_each_bad_value_is_refused_in_one_fatal_line(self):
        for number, (node, params, said) in enumerate(CASES):
            with self.subTest(node=node, params=params):
                output, status = run(number, node, params)
                fatal = [line for line in output.splitlines() if '[FATAL]' in line]
                self.assertEqual(status, 2, output)
                self.assertEqual(len(fatal), 1, output)
                self.assertIn(said, fatal[0])
                self.assertNotIn('Traceback', output)


if __name__ == '__main__':
    rostest.rosrun('turtle_letters', 'bad_parameters', BadParameters)
