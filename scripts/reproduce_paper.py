#!/usr/bin/python3
"""Reproduces the paper's Figs. 6-17: runs its scenes, renders them, and writes the report.

    scripts/reproduce_paper.py [--only ID,ID...] [--report-only] [--no-render] [--build-dir DIR]

The scenes and the paper's eleven statements are listed in scripts/paper_scenes.toml. For
each scene (or those named by --only) it runs the case driver into runs/paper/ID:
  - a folder that holds no run: a new run with the scene's settings;
  - a folder whose run stopped before its end (interrupted, or a session that ended): the
    driver continues it from its last checkpoint (--restart), with the settings it started
    with;
  - a folder whose driver finished (it holds paper_checks.csv): left as it is.
Each segment's wall time, thread count and exit code are appended to runs/paper/times.csv;
the driver's printout goes to runs/paper/ID.out. Then, unless --no-render, it renders the
scene's fields at its snapshot times with ParaView (scripts/render_fields.py under pvpython,
starting a virtual X server when there is no display) into docs/images/paper/, and writes
  docs/paper_checks.csv  every measure of every statement: figure, statement, metric, value,
                         relation, threshold, unit, met, scene, build (the run's build; two
                         joined by ';' when its segments differ); a statement whose scene
                         has not finished has one row, metric "not measured", met 0;
  docs/paper.md          per statement: the paper's statement, the measures against their
                         thresholds, met or not, the run's settings and time, the pictures.
--report-only writes the two files (and pictures) from the runs there are, running nothing.

The report is also the record. A scene whose run folder is not here (a new clone, another
machine) or has not finished keeps the measures, build and run time that the committed
docs/paper_checks.csv holds for it, and docs/paper.md says they are recorded ones; a
finished run in runs/paper/ID replaces them. To drop a scene's record (its settings or
checks changed), delete its rows from docs/paper_checks.csv.
A scene that fails (non-zero exit) is recorded and the next one runs; the exit code is 1
when any did.
"""
import argparse
import csv
import datetime
import os
import re
import shutil
import subprocess
import sys
import time
import tomllib

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
RUNS = os.path.join(ROOT, 'runs', 'paper')
IMAGES = os.path.join(ROOT, 'docs', 'images', 'paper')
TIMES_HEADER = ['scene', 'started_utc', 'wall_time_s', 'threads', 'restart', 'exit_code']
CHECK_COLUMNS = ['figure', 'statement', 'metric', 'value', 'relation', 'threshold', 'unit', 'met']
RECORD_COLUMNS = ['scene', 'build', 'run_time_s']
UNMEASURED = ('not measured', 'no measure written')


def load_scenes():
    with open(os.path.join(ROOT, 'scripts', 'paper_scenes.toml'), 'rb') as file:
        table = tomllib.load(file)
    scenes = {scene['id']: scene for scene in table['scene']}
    for statement in table['statement']:
        if statement['scene'] not in scenes:
            sys.exit(f"scripts/paper_scenes.toml: statement {statement['figure']}: scene "
                     f"\"{statement['scene']}\" is not a [[scene]]")
    return scenes, table['statement']


def run_dir(scene_id):
    return os.path.join(RUNS, scene_id)


def finished(scene_id):
    return os.path.isfile(os.path.join(run_dir(scene_id), 'paper_checks.csv'))


def run_scene(scene, build_dir, threads):
    """Runs (or continues) one scene; returns the driver's exit code."""
    folder = run_dir(scene['id'])
    driver = os.path.join(build_dir, 'cases', scene['driver'])
    restart = os.path.isfile(os.path.join(folder, 'run.log'))
    if restart:
        command = [driver, '--restart', folder, '--no-progress']
    else:
        command = [driver, '--out', folder, '--no-progress']
        for setting in scene['settings']:
            command += ['--set', setting]
    os.makedirs(RUNS, exist_ok=True)
    started = datetime.datetime.now(datetime.timezone.utc).strftime('%Y-%m-%dT%H:%M:%SZ')
    print(f"reproduce_paper: {scene['id']}: {'continuing' if restart else 'starting'} "
          f"(about {scene['hours']} h on 2 cores): {' '.join(command)}", flush=True)
    start = time.monotonic()
    # A fresh start begins the printout anew; a continuation adds to it.
    with open(os.path.join(RUNS, scene['id'] + '.out'), 'a' if restart else 'w') as printout:
        status = subprocess.call(command, stdout=printout, stderr=subprocess.STDOUT, cwd=ROOT,
                                 env=dict(os.environ, OMP_NUM_THREADS=str(threads)))
    seconds = time.monotonic() - start
    times = os.path.join(RUNS, 'times.csv')
    new = not os.path.isfile(times)
    with open(times, 'a', newline='') as file:
        writer = csv.writer(file)
        if new:
            writer.writerow(TIMES_HEADER)
        writer.writerow([scene['id'], started, f'{seconds:.0f}', threads, int(restart), status])
    print(f"reproduce_paper: {scene['id']}: exit {status} after {seconds:.0f} s", flush=True)
    return status


def wall_times():
    """The summed wall time of each scene's run [s], from runs/paper/times.csv: its segments
    since its last fresh start (a segment that is not a restart begins the run anew)."""
    total = {}
    path = os.path.join(RUNS, 'times.csv')
    if os.path.isfile(path):
        with open(path, newline='') as file:
            for row in csv.DictReader(file):
                earlier = total.get(row['scene'], 0.0) if int(row['restart']) else 0.0
                total[row['scene']] = earlier + float(row['wall_time_s'])
    return total


class VirtualDisplay:
    """An X display for pvpython: the current one, or an Xvfb started for the renders."""

    def __init__(self):
        self.process = None
        self.display = os.environ.get('DISPLAY')

    def __enter__(self):
        if not self.display:
            if not shutil.which('Xvfb'):
                raise RuntimeError('no X display and no Xvfb (Debian package xvfb)')
            number = 90 + os.getpid() % 100
            self.process = subprocess.Popen(['Xvfb', f':{number}', '-screen', '0', '1600x1200x24'],
                                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            time.sleep(2)
            self.display = f':{number}'
        return self

    def __exit__(self, *exception):
        if self.process:
            self.process.terminate()
            self.process.wait()


def snapshot_path(scene_id, seconds):
    return os.path.join(IMAGES, f'{scene_id}_t{seconds:g}s.png')


def render_scene(scene, display):
    """Renders the scene's snapshots; returns the pictures made."""
    if not shutil.which('pvpython'):
        raise RuntimeError('pvpython not found (Debian package paraview)')
    os.makedirs(IMAGES, exist_ok=True)
    view = scene['view']
    made = []
    for seconds in scene['snapshots_s']:
        out = snapshot_path(scene['id'], seconds)
        command = ['pvpython', '--disable-xdisplay-test', os.path.join(ROOT, 'scripts', 'render_fields.py'),
                   run_dir(scene['id']), out, '--time', str(seconds), '--size', '900', '650',
                   '--plasma-velocity', scene['plasma'], '--view', 'z' if view == 'oblique' else view,
                   '--caption', scene['caption']]
        if view == 'oblique':
            command.append('--oblique')
        status = subprocess.call(command, env=dict(os.environ, DISPLAY=display.display),
                                 stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT)
        if status != 0:
            print(f"reproduce_paper: {scene['id']}: rendering t = {seconds} s failed (exit {status})",
                  file=sys.stderr)
            continue
        made.append(out)
    return made


def scene_checks(scene_id):
    """The rows the scene's driver wrote, or None when it has not finished."""
    path = os.path.join(run_dir(scene_id), 'paper_checks.csv')
    if not os.path.isfile(path):
        return None
    with open(path, newline='') as file:
        return list(csv.DictReader(file))


def resolved_setting(scene_id, section, key):
    """A value from the run's case.resolved.toml, or None."""
    path = os.path.join(run_dir(scene_id), 'case.resolved.toml')
    try:
        with open(path, 'rb') as file:
            return tomllib.load(file).get(section, {}).get(key)
    except (OSError, tomllib.TOMLDecodeError):
        return None


BUILD_LINE = re.compile(r'^rouleau \S+ \(([^)]+)\): ')


def run_builds(scene_id):
    """The build (version control hash) of each segment of the run, from its run.log."""
    builds = []
    try:
        with open(os.path.join(run_dir(scene_id), 'run.log')) as log:
            for line in log:
                match = BUILD_LINE.match(line)
                if match:
                    builds.append(match.group(1))
    except OSError:
        pass
    return builds


def read_record():
    """The measures the committed docs/paper_checks.csv holds, per scene: rows, builds, seconds."""
    path = os.path.join(ROOT, 'docs', 'paper_checks.csv')
    record = {}
    if not os.path.isfile(path):
        return record
    with open(path, newline='') as file:
        for row in csv.DictReader(file):
            if row['metric'] in UNMEASURED:
                continue
            entry = record.setdefault(row['scene'], {'rows': [], 'builds': [], 'seconds': None})
            entry['rows'].append({column: row[column] for column in CHECK_COLUMNS})
            entry['builds'] = [build for build in row['build'].split(';') if build]
            if row.get('run_time_s'):
                entry['seconds'] = float(row['run_time_s'])
    return record


def scene_result(scene_id, record, times):
    """What judges a scene: its finished run here, or else the committed record, or None.

    Returns a dict with rows (every measure the driver wrote), builds (one per segment of a
    run here; the distinct ones of a recorded run), seconds (wall time, or None) and source
    ('run' or 'record').
    """
    rows = scene_checks(scene_id)
    if rows is not None:
        return {'rows': rows, 'builds': run_builds(scene_id), 'seconds': times.get(scene_id), 'source': 'run'}
    if scene_id in record:
        return dict(record[scene_id], source='record')
    return None


def statement_rows(statement, result):
    """The measures that judge the statement: the scene's rows for its figure."""
    if result is None:
        return None
    return [row for row in result['rows'] if row['figure'] == statement['figure']]


def verdict(rows):
    if rows is None:
        return 'not run'
    if not rows:
        return 'no measure'
    return 'met' if all(row['met'] == '1' for row in rows) else 'not met'


def write_checks_csv(statements, results):
    path = os.path.join(ROOT, 'docs', 'paper_checks.csv')
    with open(path + '.tmp', 'w', newline='') as file:
        writer = csv.writer(file, quoting=csv.QUOTE_MINIMAL)
        writer.writerow(CHECK_COLUMNS + RECORD_COLUMNS)
        for statement in statements:
            result = results[statement['scene']]
            rows = statement_rows(statement, result)
            build = ';'.join(sorted(set(result['builds']))) if result else ''
            seconds = f"{result['seconds']:.0f}" if result and result['seconds'] else ''
            if not rows:
                writer.writerow([statement['figure'], statement['statement'],
                                 UNMEASURED[0] if rows is None else UNMEASURED[1], '', '', '', '', 0,
                                 statement['scene'], build, seconds])
                continue
            for row in rows:
                writer.writerow([statement['figure'], statement['statement']] +
                                [row[column] for column in CHECK_COLUMNS[2:]] + [statement['scene'], build, seconds])
    os.replace(path + '.tmp', path)
    return path


def format_hours(seconds):
    return f'{seconds / 60:.0f} min' if seconds < 5400 else f'{seconds / 3600:.1f} h'


def write_markdown(scenes, statements, results):
    lines = [
        '# The paper, reproduced',
        '',
        'Each of the eleven result statements of Liu, Zhang, Wang et al. (2004), "Coupling of',
        'Navier–Stokes equations with protein molecular dynamics and its application to',
        'hemodynamics", Figs. 6–17, checked on one straight run of a scene: the measures the',
        "case's driver computes from the run's diagnostics, each against a threshold fixed",
        'before the run (`src/analysis/scene_checks.hpp`, `src/analysis/paper_checks.hpp`). A',
        'statement is met when every one of its measures is. The pictures are rendered by',
        "ParaView from each run's own `fields.xdmf` (`scripts/render_fields.py`).",
        '',
        'This page and [`paper_checks.csv`](paper_checks.csv) (every measure, machine-readable)',
        'are written by',
        '',
        '```sh',
        'scripts/reproduce_paper.sh                    # every scene; continues stopped runs',
        'scripts/reproduce_paper.sh --only stack_0.25  # one scene',
        'scripts/reproduce_paper.sh --report-only      # this page from runs/paper and the record',
        '```',
        '',
        'from the scenes listed in `scripts/paper_scenes.toml`; a stopped run continues from its',
        'last checkpoint with the settings it started with. The run times below are wall times',
        'on the machine named in each run\'s log, summed over its segments. The csv file is also',
        'the record: a scene whose run is not on the machine that writes this page keeps the',
        'measures, build and run time recorded there, and its section says so.',
        '',
        '| figure | statement | outcome | scene | run time |',
        '|---|---|---|---|---|',
    ]
    counts = {}
    for statement in statements:
        result = results[statement['scene']]
        rows = statement_rows(statement, result)
        outcome = verdict(rows)
        counts[outcome] = counts.get(outcome, 0) + 1
        seconds = result['seconds'] if result else None
        shown = f'**{outcome}**' if outcome == 'met' else outcome
        anchor = statement['figure'].lower().replace('. ', '-').replace(' ', '-')
        lines.append(f"| [{statement['figure']}](#{anchor}) | {statement['statement']} | {shown} | "
                     f"`{statement['scene']}` | {format_hours(seconds) if seconds else '—'} |")
    lines += ['', ', '.join(f'{count} {outcome}' for outcome, count in sorted(counts.items())) + '.', '']
    for statement in statements:
        scene = scenes[statement['scene']]
        result = results[statement['scene']]
        rows = statement_rows(statement, result)
        lines += [f"## {statement['figure']}", '', f"*{statement['statement']}*", '']
        command = f"build/cases/{scene['driver']} --out runs/paper/{scene['id']}" + ''.join(
            f" --set '{setting}'" for setting in scene['settings'])
        lines += ['```sh', command, '```', '']
        builds = result['builds'] if result else []
        if result and result['source'] == 'record':
            distinct = sorted(set(builds))
            if len(distinct) == 1:
                lines += [f"Run by build `{distinct[0]}` (one binary); the measures below are the recorded "
                          "ones: no finished run of this scene was on the machine that wrote this page.", '']
            else:
                lines += [f"**Run by {len(distinct)} different builds** (" + ', '.join(f'`{build}`' for build in distinct)
                          + "): not one straight run. The measures below are the recorded ones.", '']
        elif builds:
            distinct = sorted(set(builds))
            segments = f'{len(builds)} segment' + ('s' if len(builds) > 1 else '')
            if len(distinct) == 1:
                lines += [f"Run by build `{distinct[0]}` ({segments}, one binary).", '']
            else:
                lines += [f"**Run by {len(distinct)} different builds** ({segments}: "
                          + ', '.join(f'`{build}`' for build in builds) + '): not one straight run.', '']
        if statement.get('note'):
            lines += [statement['note'].strip(), '']
        if rows is None:
            lines += ['Not run to its end yet.', '']
        elif not rows:
            lines += ['The run finished but its driver wrote no measure for this figure.', '']
        else:
            lines += ['| measure | value | threshold | met |', '|---|---|---|---|']
            for row in rows:
                unit = f" {row['unit']}" if row['unit'] else ''
                metric = row['metric'].replace('|', '\\|')  # |x| would split the table's cells
                lines.append(f"| {metric} | {float(row['value']):.4g}{unit} | {row['relation']} "
                             f"{float(row['threshold']):.4g}{unit} | {'yes' if row['met'] == '1' else 'no'} |")
            lines += ['', f"**{verdict(rows)}**.", '']
        pictures = [snapshot_path(scene['id'], seconds) for seconds in scene['snapshots_s']]
        pictures = [(seconds, path) for seconds, path in zip(scene['snapshots_s'], pictures) if os.path.isfile(path)]
        if pictures:
            lines.append(' '.join(
                f"![{scene['id']} at t = {seconds:g} s](images/paper/{os.path.basename(path)})"
                for seconds, path in pictures))
            lines += ['', f"*`{scene['id']}` at t = " + ', '.join(f'{seconds:g}' for seconds, _ in pictures) +
                      ' s: the cells coloured by their displacement since t = 0, the plasma by its velocity.*', '']
    path = os.path.join(ROOT, 'docs', 'paper.md')
    with open(path + '.tmp', 'w') as file:
        file.write('\n'.join(lines))
    os.replace(path + '.tmp', path)
    return path


def main():
    parser = argparse.ArgumentParser(description="Reproduces the paper's Figs. 6-17.")
    parser.add_argument('--only', help='comma-separated scene ids (scripts/paper_scenes.toml)')
    parser.add_argument('--report-only', action='store_true', help='run nothing; render and write the report')
    parser.add_argument('--no-render', action='store_true', help='no pictures')
    parser.add_argument('--build-dir', default=os.environ.get('BUILD_DIR', os.path.join(ROOT, 'build')))
    parser.add_argument('--threads', type=int, default=int(os.environ.get('OMP_NUM_THREADS', os.cpu_count())))
    arguments = parser.parse_args()
    scenes, statements = load_scenes()
    chosen = list(scenes)
    if arguments.only:
        chosen = arguments.only.split(',')
        unknown = [scene_id for scene_id in chosen if scene_id not in scenes]
        if unknown:
            sys.exit(f"reproduce_paper: --only: no scene {', '.join(unknown)} in scripts/paper_scenes.toml "
                     f"(scenes: {', '.join(scenes)})")
    failed = []
    if not arguments.report_only:
        for scene_id in chosen:
            if finished(scene_id):
                print(f'reproduce_paper: {scene_id}: finished earlier (runs/paper/{scene_id}); left as it is')
                continue
            if run_scene(scenes[scene_id], arguments.build_dir, arguments.threads) != 0:
                failed.append(scene_id)
    if not arguments.no_render:
        with VirtualDisplay() as display:
            for scene_id in chosen:
                if os.path.isfile(os.path.join(run_dir(scene_id), 'fields_fluid.xdmf')):
                    render_scene(scenes[scene_id], display)
    record = read_record()
    times = wall_times()
    results = {scene_id: scene_result(scene_id, record, times) for scene_id in scenes}
    print('reproduce_paper: wrote', write_checks_csv(statements, results), 'and',
          write_markdown(scenes, statements, results))
    if failed:
        print(f"reproduce_paper: failed: {', '.join(failed)} (runs/paper/ID.out)", file=sys.stderr)
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
