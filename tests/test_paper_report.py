#!/usr/bin/python3
"""The paper report keeps what it cannot measure again: scripts/reproduce_paper.py --report-only
in a scratch copy of the project, with a committed record (docs/paper_checks.csv) for two
scenes and a finished run here for one of them.

Asserts that
  - a scene with no run here keeps its recorded measures, build and run time, and its
    section in docs/paper.md says they are recorded;
  - a finished run here replaces the record of its scene (value, build, time), its time
    the sum of its segments since its last fresh start;
  - a scene with neither is "not measured", met 0;
  - the rows that say "not measured" in the record are not taken as measures.
Exit 0 when all hold; otherwise the first failure, exit 1.
"""
import csv
import os
import shutil
import subprocess
import sys
import tempfile

SOURCE = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
HEADER = ['figure', 'statement', 'metric', 'value', 'relation', 'threshold', 'unit', 'met',
          'scene', 'build', 'run_time_s']
FIG6 = 'Two cells near each other in plasma at rest aggregate: the gap closes to the order of r0 and stays there.'
FIG10 = 'At 0.5 1/s the aggregate aligns with the flow and starts to come apart, by 1 s.'
FIG11 = 'At 3.0 1/s the aggregate breaks up completely into parallel layers, by 0.5 s.'


def fail(message):
    print('test_paper_report: FAILED:', message)
    sys.exit(1)


def write_csv(path, header, rows):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, 'w', newline='') as file:
        writer = csv.writer(file)
        writer.writerow(header)
        writer.writerows(rows)


def main():
    with tempfile.TemporaryDirectory() as root:
        os.makedirs(os.path.join(root, 'scripts'))
        for name in ('reproduce_paper.py', 'paper_scenes.toml'):
            shutil.copy(os.path.join(SOURCE, 'scripts', name), os.path.join(root, 'scripts', name))
        # The committed record: Fig. 6 (aggregation) and Fig. 10 (stack_0.5) measured by build
        # aaaa; Fig. 11 recorded as not measured.
        write_csv(os.path.join(root, 'docs', 'paper_checks.csv'), HEADER, [
            ['Fig. 6', FIG6, 'final gap', '0.27', '<', '0.375', 'um', '1', 'aggregation', 'aaaa', '67'],
            ['Fig. 10', FIG10, 'largest gap growth', '0.02', '>', '0.25', 'um', '0', 'stack_0.5', 'aaaa', '623'],
            ['Fig. 11', FIG11, 'not measured', '', '', '', '', '0', 'stack_3.0', 'aaaa', ''],
        ])
        # A finished run of stack_0.5 here, by build bbbb: an abandoned start (400 s), then a
        # fresh start interrupted after 700 s and continued for 200 s: 900 s.
        run = os.path.join(root, 'runs', 'paper', 'stack_0.5')
        write_csv(os.path.join(run, 'paper_checks.csv'), HEADER[:8], [
            ['Fig. 10', FIG10, 'largest gap growth', '0.31', '>', '0.25', 'um', '1']])
        with open(os.path.join(run, 'run.log'), 'w') as log:
            log.write('rouleau 0.9.0 (bbbb): case_stack_shear\n')
        write_csv(os.path.join(root, 'runs', 'paper', 'times.csv'),
                  ['scene', 'started_utc', 'wall_time_s', 'threads', 'restart', 'exit_code'],
                  [['stack_0.5', '2026-01-01T00:00:00Z', '400', '2', '0', '4'],
                   ['stack_0.5', '2026-01-02T00:00:00Z', '700', '2', '0', '4'],
                   ['stack_0.5', '2026-01-02T01:00:00Z', '200', '2', '1', '0']])

        status = subprocess.call(['/usr/bin/python3', os.path.join(root, 'scripts', 'reproduce_paper.py'),
                                  '--report-only', '--no-render'], stdout=subprocess.DEVNULL)
        if status != 0:
            fail(f'reproduce_paper.py --report-only exited {status}')
        with open(os.path.join(root, 'docs', 'paper_checks.csv'), newline='') as file:
            rows = list(csv.DictReader(file))
        by_figure = {}
        for row in rows:
            by_figure.setdefault(row['figure'], []).append(row)

        fig6 = by_figure.get('Fig. 6', [])
        if len(fig6) != 1 or fig6[0]['value'] != '0.27' or fig6[0]['build'] != 'aaaa' \
                or fig6[0]['run_time_s'] != '67' or fig6[0]['met'] != '1':
            fail(f'Fig. 6 should keep its record (0.27, aaaa, 67 s, met): {fig6}')
        fig10 = by_figure.get('Fig. 10', [])
        if len(fig10) != 1 or fig10[0]['value'] != '0.31' or fig10[0]['build'] != 'bbbb' \
                or fig10[0]['run_time_s'] != '900' or fig10[0]['met'] != '1':
            fail(f'Fig. 10 should come from the run here (0.31, bbbb, 900 s, met): {fig10}')
        fig11 = by_figure.get('Fig. 11', [])
        if len(fig11) != 1 or fig11[0]['metric'] != 'not measured' or fig11[0]['met'] != '0':
            fail(f'Fig. 11 should stay not measured: {fig11}')
        fig12 = by_figure.get('Fig. 12', [])
        if len(fig12) != 1 or fig12[0]['metric'] != 'not measured':
            fail(f'Fig. 12 (no record, no run) should be not measured: {fig12}')

        with open(os.path.join(root, 'docs', 'paper.md')) as file:
            page = file.read()
        section6 = page[page.index('## Fig. 6'):page.index('## Fig. 7')]
        if 'recorded' not in section6 or '`aaaa`' not in section6:
            fail('the Fig. 6 section should name build aaaa and say its measures are recorded')
        section10 = page[page.index('## Fig. 10'):page.index('## Fig. 11')]
        if 'recorded' in section10 or '`bbbb`' not in section10:
            fail('the Fig. 10 section should name build bbbb and not say recorded')
    print('test_paper_report: the record is kept where there is no run, and replaced by a run')
    return 0


if __name__ == '__main__':
    sys.exit(main())
