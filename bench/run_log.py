"""Reading a `rouleau run` log and a case file's time step, for the bench scripts."""
import re
import sys

STAGE_LINE = re.compile(r"^\s{2}(\S.*?)\s{2,}([0-9.]+) s(?:\s+[0-9.]+ %)?$")
# The table's last two lines are not stages: the time outside them and the total.
NOT_STAGES = ("outside the stages", "total")


def stage_times(log):
    """The 'time per stage:' table at the end of a run's log, as {stage: seconds}."""
    times, inside = {}, False
    for line in log.splitlines():
        if line.startswith("time per stage:"):
            inside = True
            continue
        if inside:
            match = STAGE_LINE.match(line)
            if not match:
                break
            if match.group(1).strip() not in NOT_STAGES:
                times[match.group(1).strip()] = float(match.group(2))
    return times


TIME_STEP = re.compile(r"^dt_s\s*=\s*([0-9.eE+-]+)", re.M)


def case_time_step(case_file):
    """The case file's time.dt_s [s] (exits naming the file when it has none)."""
    with open(case_file) as f:
        match = TIME_STEP.search(f.read())
    if not match:
        sys.exit(f"{case_file}: no time.dt_s")
    return float(match.group(1))
