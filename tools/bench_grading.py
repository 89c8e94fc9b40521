"""`make bench`'s grading group: a class graded by grade_class.py.

- A class of copies of the test class's submissions of every shape
  (MODELS), as many students as asked (30 by default), graded with
  --jobs 2: minutes
  per class, each student's grading time beyond their drawing (build,
  launch, the wait before the key, the settle), and the most memory the
  grader's own process held (VmHWM).
- Fairness: the lab's own busy-loop controller (c01_nadia) graded alone
  three times, against its copies graded in that class: the same verdict
  and letter, and a worst deviation within the spread of the runs alone.
- The sandbox's cost: Lena's L (c03_lena) graded three times in the
  sandbox and three times with --no-sandbox (inside a bubblewrap container
  of the bench's own, as Gradescope's container would hold it): the
  seconds to build and launch, the steps it wraps; and the sandbox made,
  used once and removed.
- The cost of owning the world: the grader's master and simulator for one
  student started (to the simulator's first turtle), then their CPU (% of
  a core) and memory over WORLD_WATCH s with the turtle standing, as while
  a package builds its nodes or waits for the key.
"""
import csv
import json
import os
import re
import shutil
import statistics
import subprocess
import tempfile
import time

# bench.py puts test/ on the path
from support.grading import container, peak_memory_kb, started_grading

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), '..'))
CLASS = os.path.join(REPO, 'test', 'class')
# A class of every shape: the lab's own, closed loops, a wrong letter, one
# drawing at launch, one without a launch file, a turtle of their own, pen
# lifts, initials and C++.
MODELS = [('c01_nadia', 'Nadia Novak', ''), ('c02_kofi', 'Kofi Mensah', ''),
          ('c03_lena', 'Lena Ortiz', ''), ('c04_maria', 'Maria Silva', ''),
          ('c15_carmen', 'Carmen Diaz', ''), ('c16_noah', 'Noah Klein', ''),
          ('c18_theo', 'Theo Jansen', ''), ('c19_farah', 'Farah Nasser', ''),
          ('c20_jonas', 'Jonas Dahl', 'JD'), ('c21_hana', 'Hana Sato', '')]
LAB = 'c01_nadia'
CLASS_TARGET_MIN, OVERHEAD_TARGET_S = 15.0, 15.0    # for 30 students on 2 cores
SANDBOX_TARGET_S = 2.0      # the most the sandbox may add to a student's grading
GRADER_MEMORY_TARGET_MIB = 400  # the grader's own process, whatever a class prints (test_odd_class)


def _grade(*args):
    return subprocess.run(['rosrun', 'turtle_letters', 'grade_class.py', *args],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, env=dict(os.environ, PYTHONUNBUFFERED='1'))


def _results(out, student):
    with open(os.path.join(out, student, 'results.json')) as f:
        data = json.load(f)
    board = {b['name']: b['value'] for b in data['leaderboard']}
    return data, board


def _row(out, student):
    with open(os.path.join(out, 'grades.csv')) as f:
        return next(r for r in csv.DictReader(f) if r['id'] == student)


def class_run(students, keep, jobs=2):
    """Grade `students` copies of the models; minutes, and each one's
    overhead. The grades stay in `keep`/grade_class, to look at."""
    top = tempfile.mkdtemp(prefix='bench_class_')
    out = os.path.join(keep, 'grade_class')
    shutil.rmtree(out, ignore_errors=True)
    try:
        subs = os.path.join(top, 'submissions')
        with open(os.path.join(top, 'roster.csv'), 'w') as f:
            f.write('id,name,letter\n')
            for i in range(students):
                model, name, letter = MODELS[i % len(MODELS)]
                shutil.copytree(os.path.join(CLASS, 'submissions', model),
                                os.path.join(subs, f's{i + 1:02}_{model}'), symlinks=True)
                f.write(f's{i + 1:02}_{model},{name},{letter}\n')
        started = time.monotonic()
        grading = started_grading(subs, '--roster', os.path.join(top, 'roster.csv'), '--out', out,
                                  '--jobs', str(jobs))
        memory, printed = peak_memory_kb(grading)
        minutes = (time.monotonic() - started) / 60
        if grading.returncode != 0:
            raise RuntimeError(f'grade_class.py failed:\n{printed[-3000:]}')
        overheads, lab = [], []
        for i in range(students):
            student = f's{i + 1:02}_{MODELS[i % len(MODELS)][0]}'
            data, board = _results(out, student)
            overheads.append((data['execution_time'] - board.get('drawing time (s)', 0.0),
                              student))
            if student.endswith(LAB):
                row = _row(out, student)
                lab.append(dict(verdict=row['verdict'], drawn=row['drawn'],
                                fit_pct=board.get('worst deviation (% of height)')))
        worst = max(overheads)
        return dict(students=students, jobs=jobs, minutes=minutes,
                    overhead_median_s=statistics.median(o for o, _ in overheads),
                    overhead_worst_s=worst[0], overhead_worst_student=worst[1], lab_in_class=lab,
                    grader_mib=memory / 1024)
    finally:
        shutil.rmtree(top, ignore_errors=True)


def alone_runs(reps=3):
    """The lab's submission graded alone, `reps` times."""
    runs = []
    for _ in range(reps):
        out = tempfile.mkdtemp(prefix='bench_alone_')
        try:
            _grade('--one', os.path.join(CLASS, 'submissions', LAB), '--name', 'Nadia', '--out',
                   out)
            _, board = _results(out, LAB)
            row = _row(out, LAB)
            runs.append(dict(verdict=row['verdict'], drawn=row['drawn'],
                             fit_pct=board.get('worst deviation (% of height)')))
        finally:
            shutil.rmtree(out, ignore_errors=True)
    return runs


def _build_and_launch(results):
    """Seconds to build and to launch, from their criteria's lines: the
    steps the sandbox wraps (the drawing takes as long either way, and the
    stop is a kill in the sandbox but Ctrl-C and roslaunch's wait without)."""
    said = {t['name']: t['output'] for t in results['tests']}
    built = re.search(r'built in ([\d.]+) s', said['It builds'])
    up = re.search(r' in ([\d.]+) s$', said['It launches'])
    return float(built.group(1)) + float(up.group(1))


def sandbox_cost(reps=3):
    """Seconds to build and launch Lena's package in the sandbox and
    without it, `reps` times each, and to make and remove the sandbox alone."""
    from turtle_letters.isolation.sandbox import Sandbox
    lena = os.path.join(CLASS, 'submissions', 'c03_lena')
    times = {'sandboxed': [], 'unsandboxed': []}
    for _ in range(reps):
        for kind in times:
            out = tempfile.mkdtemp(prefix='bench_sandbox_')
            try:
                args = ['--one', lena, '--letter', 'L', '--out', out]
                if kind == 'sandboxed':
                    _grade(*args)
                else:
                    subprocess.run(container(out) + ['rosrun', 'turtle_letters',
                                                      'grade_class.py', *args, '--no-sandbox'],
                                   stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT)
                times[kind].append(_build_and_launch(_results(out, 'c03_lena')[0]))
            finally:
                shutil.rmtree(out, ignore_errors=True)
    made = []
    for _ in range(reps):
        started = time.monotonic()
        with Sandbox(_caps()) as box:
            subprocess.run(box.inside(['true'], {}), check=True)
        made.append(time.monotonic() - started)
    return dict(times, made_s=statistics.median(made), world=[world_cost() for _ in range(reps)])


WORLD_WATCH = 10.0      # s the grader's world is watched idle


def _user_usage(user):
    """(CPU s, resident MiB) of every process of `user`."""
    cpu = memory = 0.0
    for pid in filter(str.isdigit, os.listdir('/proc')):
        try:
            if os.stat(f'/proc/{pid}').st_uid != user:
                continue
            with open(f'/proc/{pid}/stat') as f:
                fields = f.read().rsplit(')', 1)[1].split()
            cpu += (int(fields[11]) + int(fields[12])) / os.sysconf('SC_CLK_TCK')
            memory += int(fields[21]) * os.sysconf('SC_PAGE_SIZE') / 2 ** 20
        except (OSError, ValueError, IndexError):
            continue
    return cpu, memory


def _caps():
    from turtle_letters.autograder.cli import default_limits
    from turtle_letters.autograder.session import caps
    return caps(default_limits())


def world_cost():
    """One student's world: seconds to start it, then its idle CPU and memory."""
    from turtle_letters.isolation.sandbox import Sandbox
    from turtle_letters.autograder.cli import default_limits
    from turtle_letters.autograder.world import GradingWorld
    with Sandbox(_caps()) as box:
        world = GradingWorld(box, default_limits())
        try:
            started = time.monotonic()
            world.start()
            up = time.monotonic() - started
            before = _user_usage(box.beside.user)[0]
            time.sleep(WORLD_WATCH)
            cpu, memory = _user_usage(box.beside.user)
        finally:
            world.stop()
    return dict(up_s=up, cpu_pct=100 * (cpu - before) / WORLD_WATCH, mib=memory)


def grading_lines(results):
    lines = ['']
    c = results.get('grade_class')
    if c:
        lines.append(
            f"grade_class.py, {c['students']} students, --jobs {c['jobs']}: "
            f"{c['minutes']:.1f}{'!' if c['minutes'] > CLASS_TARGET_MIN * c['students'] / 30 else ''}"
            f" min; beyond each drawing median {c['overhead_median_s']:.1f} s, worst "
            f"{c['overhead_worst_s']:.1f}{'!' if c['overhead_worst_s'] > OVERHEAD_TARGET_S else ''} s "
            f"({c['overhead_worst_student']}); the grader's own memory at most "
            f"{c['grader_mib']:.0f}{'!' if c['grader_mib'] > GRADER_MEMORY_TARGET_MIB else ''} MiB")
    alone = results.get('grade_alone')
    if alone and c:
        fits = [r['fit_pct'] for r in alone]
        spread = max(fits) - min(fits)
        inside = [r['fit_pct'] for r in c['lab_in_class']]
        far = max(abs(f - statistics.median(fits)) for f in inside) if inside else 0.0
        same = {(r['verdict'], r['drawn']) for r in alone + c['lab_in_class']}
        lines.append(
            f"fairness, the lab's busy-loop N: alone {', '.join(f'{f:.2f}' for f in fits)}% of the "
            f"height (spread {spread:.2f}); in the class {', '.join(f'{f:.2f}' for f in inside)}% "
            f"(farthest from the median alone {far:.2f}{'!' if far > max(spread, 0.01) else ''}); "
            f"verdicts and letters {sorted(same)}{'!' if len(same) > 1 else ''}")
    cost = results.get('sandbox_cost')
    if cost:
        inside, outside = (statistics.median(cost[k]) for k in ('sandboxed', 'unsandboxed'))
        lines.append(
            f"the sandbox: Lena's L built and launched in it "
            f"{', '.join(f'{t:.1f}' for t in cost['sandboxed'])} s, without it "
            f"{', '.join(f'{t:.1f}' for t in cost['unsandboxed'])} s: "
            f"{inside - outside:+.2f}{'!' if inside - outside > SANDBOX_TARGET_S else ''} s "
            f"(medians); made, used once and removed: {1000 * cost['made_s']:.0f} ms")
        worlds = cost.get('world', [])
        if worlds:
            ups = ', '.join(f"{w['up_s']:.1f}" for w in worlds)
            lines.append(
                f"the grader's own world per student (rosmaster and the simulator): up in {ups} s; "
                f"idle "
                f"{statistics.median(w['cpu_pct'] for w in worlds):.1f}% of a core, "
                f"{statistics.median(w['mib'] for w in worlds):.0f} MiB (medians)")
    lines.append(f'Grading targets: {CLASS_TARGET_MIN:g} min for 30 students on 2 cores; '
                 f'<= {OVERHEAD_TARGET_S:g} s per student beyond the drawing; the same verdict '
                 f'and letter alone and in a class, the deviation within the spread alone; the sandbox '
                 f'adds <= {SANDBOX_TARGET_S:g} s; the grader holds <= {GRADER_MEMORY_TARGET_MIB} MiB.')
    return lines
