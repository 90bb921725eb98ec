#!/usr/bin/python3
"""Stability map (bench/stability.md): short reduced runs swept over the time step, for each
coupling scheme, against the explicit coupling's predicted stable step (rouleau check
prints it: C μ h_f / G_eff), over the cell stiffness (normal to sickle), the shear rate
(0.25 to 100 1/s), the Morse strength, and three hard cases on purpose: two cells touching
at the start, a cell pressed against a wall, a capsule in a capillary narrower than half
its diameter.

Each run ends one of four ways, and the map shows which:
  stable    exit 0, no NaN in the diagnostics, volumes within 1 % of the start;
  diverged  exit 3 with the divergence message (step, stage, values) naming a last good
            checkpoint that exists and is whole: the clean failure of docs/running.md, "Divergence";
  drifting  exit 0 with a volume off by more than 1 % after --steps steps. Such a run is
            run again for --confirm-steps steps: if it then stops with the divergence
            message it is *diverged* (late), if it still ends with exit 0 and its volumes
            within the run's own tolerance (coupling.volume_tolerance) it stays
            *drifting*: degraded, never silent (the diagnostics show the drift);
  FAILURE   anything else: a crash, another exit code, a diverged run without its
            checkpoint, NaN with exit 0, or a volume beyond the run's tolerance with exit 0.
The script exits 1 if any run is a FAILURE. Rows are appended to OUT.part as they come;
--resume continues from it.

    /usr/bin/python3 bench/stability.py [--rouleau build/rouleau] [--quick] [--steps 30]
        [--confirm-steps 300] [--resume] [--out bench/stability.csv]   (figure beside it, .png)
"""
import argparse
import csv
import math
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STABLE_STEP = re.compile(r"explicit stable step estimate ([0-9.eE+-]+) s")
LAST_GOOD = re.compile(r"last good checkpoint: (\S+\.h5)")

# The reduced one-cell shear box (cases/rbc_shear at h_f = 1.33 μm, coarse cell) and the
# reduced two-cell aggregation (cases/aggregation at h_f = 1 μm, coarse cells).
SHEAR = ("rbc_shear", ["domain.elements=[18,12,12]", "cell_kinds.normal.resolution=\"coarse\""])
AGGREGATION = ("aggregation", ["domain.elements=[12,12,10]", "cell_kinds.normal.resolution=\"coarse\""])
# The capsule starts in the inlet feeder, its front 1 μm from the contraction, and a fast
# inflow (2 mm/s) drives it into the entrance within the run's steps.
CAPILLARY = ("capillary", ["vessel.element_size_um=3.0", "vessel.wall_element_size_um=1.0",
                           "cells=[{kind=\"capsule\", center_um=[12.0, 0, 0]}]", "boundary.inlet.mean_speed_um_s=2000.0"])


def wall_speeds(shear_rate):
    """Wall velocities [μm/s] of the 16 μm high shear box for a shear rate [1/s]."""
    u = 8.0 * shear_rate
    return [f"boundary.y_min.velocity_um_s=[{-u!r},0.0,0.0]", f"boundary.y_max.velocity_um_s=[{u!r},0.0,0.0]"]


def families(quick):
    """(family, variant label, case, overrides) of every scene swept."""
    scenes = []
    for rate in ([3.0] if quick else [0.25, 3.0, 30.0, 100.0]):
        scenes.append(("shear rate", f"{rate:g} 1/s", SHEAR[0], SHEAR[1] + wall_speeds(rate)))
    if not quick:
        # Normal (4.2 pN/μm membrane, G = 11.7 kPa over 0.36 μm) and sickle-stiff (G × 10).
        for factor in (1, 10):
            scenes.append(("stiffness", f"G x {factor}", SHEAR[0],
                           SHEAR[1] + wall_speeds(30.0) + [f"cell_kinds.normal.membrane_shear_modulus_pN_um={4.2 * factor!r}"]))
        for strength in (1.0, 5.0, 25.0):
            scenes.append(("Morse strength", f"De x {strength:g}", AGGREGATION[0],
                           AGGREGATION[1] + [f"interaction.strength_multiplier={strength!r}"]))
    # Hard cases.
    scenes.append(("hard", "cells touching (0.01 um)", AGGREGATION[0],
                   AGGREGATION[1] + ["cells=[{kind=\"normal\", center_um=[0.0,0.0,-1.29]}, "
                                     "{kind=\"normal\", center_um=[0.0,0.0,1.29]}]"]))
    if not quick:
        scenes.append(("hard", "cell 0.2 um from a wall", SHEAR[0],
                       SHEAR[1] + wall_speeds(30.0) +
                       ["cells=[{kind=\"normal\", center_um=[0.0,-3.89,0.0], orientation_deg=[0.0,0.0,0.0]}]"]))
        scenes.append(("hard", "capsule, capillary < half its diameter", CAPILLARY[0],
                       CAPILLARY[1] + ["vessel.throat_radius_um=1.4"]))
    return scenes


def stable_step(rouleau, case_file, overrides):
    # The estimate is printed for any step; the run may exceed it on purpose.
    settings = overrides + ["coupling.allow_unstable_step=true"]
    command = [rouleau, "check", case_file] + [a for o in settings for a in ("--set", o)]
    done = subprocess.run(command, capture_output=True, text=True)
    match = STABLE_STEP.search(done.stdout)
    if done.returncode != 0 or not match:
        sys.exit(f"stability.py: {' '.join(command)}: no stable step estimate\n{done.stdout}{done.stderr}")
    return float(match.group(1))


def diagnostics_health(folder):
    """(any NaN, largest relative volume change) over the diagnostics rows."""
    path = os.path.join(folder, "diagnostics.csv")
    if not os.path.exists(path):
        return True, float("nan")
    with open(path) as f:
        rows = list(csv.DictReader(f))
    # A column that is NaN from its first row is undefined by design in this scene (the
    # relative apparent viscosity without a shear rate, a wall's stress without the wall);
    # NaN appearing later is the failure looked for.
    def finite(v):
        return v in ("", None) or math.isfinite(float(v))
    undefined = {k for k, v in rows[0].items() if not finite(v)} if rows else set()
    nan = any(not finite(v) for r in rows for k, v in r.items() if k not in undefined)
    drift = max((float(r.get("largest_relative_volume_change", 0.0) or 0.0) for r in rows), default=0.0)
    return nan, drift


VOLUME_TOLERANCE = 0.1  # coupling.volume_tolerance's default: a run stops beyond it


def classify(done, folder):
    nan, drift = diagnostics_health(folder)
    if done.returncode == 0:
        if nan:
            return "FAILURE", "exit 0 with NaN in the diagnostics", drift
        if not drift <= VOLUME_TOLERANCE:
            return "FAILURE", f"exit 0 with a volume drift of {drift:.2e}, beyond the run's tolerance", drift
        if not drift < 0.01:
            return "drifting", f"exit 0 with a volume drift of {drift:.2e}", drift
        return "stable", "", drift
    if done.returncode == 3:
        message = done.stderr.strip().splitlines()[-1] if done.stderr.strip() else ""
        checkpoint = LAST_GOOD.search(done.stderr)
        if "diverged at step" not in done.stderr or not checkpoint:
            return "FAILURE", "exit 3 without the step or the last good checkpoint: " + message, drift
        if not os.path.isfile(checkpoint.group(1)):
            return "FAILURE", "the named checkpoint does not exist: " + checkpoint.group(1), drift
        return "diverged", message, drift
    return "FAILURE", f"exit code {done.returncode}: " + done.stderr.strip()[-300:], drift


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--rouleau", default=os.path.join(ROOT, "build", "rouleau"))
    parser.add_argument("--steps", type=int, default=30)
    parser.add_argument("--quick", action="store_true", help="one shear rate and one hard case, three steps sizes")
    parser.add_argument("--confirm-steps", type=int, default=300,
                        help="steps of the second run of a drifting run")
    parser.add_argument("--resume", action="store_true", help="skip the runs already in OUT.part")
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--out", default=os.path.join(ROOT, "bench", "stability.csv"))
    args = parser.parse_args()
    factors = [0.5, 2.0, 8.0] if args.quick else [0.25, 0.5, 1.0, 1.5, 2.0, 4.0, 8.0, 16.0]
    fields = ["family", "variant", "scheme", "dt_s", "stable_estimate_s", "dt_over_estimate", "outcome",
              "largest_volume_change", "steps", "detail"]
    part = args.out + ".part"
    rows = []
    if args.resume and os.path.exists(part):
        with open(part) as f:
            rows = list(csv.DictReader(f))
        for r in rows:
            r["dt_over_estimate"] = float(r["dt_over_estimate"])
    done_keys = {(r["family"], r["variant"], r["scheme"], float(r["dt_over_estimate"])) for r in rows}
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    with open(part, "w", newline="") as log, tempfile.TemporaryDirectory(prefix="rouleau-stability-") as scratch:
        writer = csv.DictWriter(log, fieldnames=fields)
        writer.writeheader()
        writer.writerows(rows)
        log.flush()  # the resumed rows are on disk before the first new run
        for family, label, case, overrides in families(args.quick):
            if all((family, label, scheme, factor) in done_keys
                   for scheme in ("explicit", "semi_implicit") for factor in factors):
                continue
            case_file = os.path.join(ROOT, "cases", case, "case.toml")
            dt_stable = stable_step(args.rouleau, case_file, overrides)
            for scheme in ("explicit", "semi_implicit"):
                for factor in factors:
                    if (family, label, scheme, factor) in done_keys:
                        continue
                    dt = factor * dt_stable

                    def run(steps):
                        folder = os.path.join(scratch, f"run{len(rows)}_{steps}")
                        settings = overrides + [f"coupling.scheme=\"{scheme}\"", f"time.dt_s={dt!r}",
                                                f"time.end_s={steps * dt!r}", "output.fields=false",
                                                "output.diagnostics_every_steps=1", "coupling.allow_unstable_step=true"]
                        command = [args.rouleau, "run", case_file, "--out", folder, "--no-progress",
                                   "--threads", str(args.threads)] + [a for o in settings for a in ("--set", o)]
                        return classify(subprocess.run(command, capture_output=True, text=True), folder)

                    steps = args.steps
                    outcome, detail, drift = run(steps)
                    if outcome == "drifting":
                        short_drift = drift
                        steps = args.confirm_steps
                        outcome, detail, drift = run(steps)
                        detail = f"after {args.steps} steps a volume drift of {short_drift:.2e}; over {steps}: " + \
                                 (detail or f"exit 0, drift {drift:.2e}")
                    row = {"family": family, "variant": label, "scheme": scheme, "dt_s": dt,
                           "stable_estimate_s": dt_stable, "dt_over_estimate": factor, "outcome": outcome,
                           "largest_volume_change": drift, "steps": steps, "detail": detail}
                    rows.append(row)
                    writer.writerow(row)
                    log.flush()
                    print(f"{family:15s} {label:40s} {scheme:14s} dt = {factor:5g} x {dt_stable:.3g} s: {outcome}"
                          f"{' (' + detail + ')' if detail else ''}", flush=True)
    os.replace(part, args.out)
    plot(rows, os.path.splitext(args.out)[0] + ".png", args.steps)
    failures = [r for r in rows if r["outcome"] == "FAILURE"]
    print(f"wrote {args.out}; {len(rows)} runs, {len(failures)} failures")
    return 1 if failures else 0


def plot(rows, path, steps):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    scenes = []
    for r in rows:
        key = (r["family"], r["variant"])
        if key not in scenes:
            scenes.append(key)
    colors = {"stable": "tab:green", "drifting": "gold", "diverged": "tab:orange", "FAILURE": "tab:red"}
    figure, axes = plt.subplots(1, 2, figsize=(13, 0.45 * len(scenes) + 2), sharey=True)
    for ax, scheme in zip(axes, ("explicit", "semi_implicit")):
        for y, key in enumerate(scenes):
            for r in rows:
                if (r["family"], r["variant"]) == key and r["scheme"] == scheme:
                    ax.scatter(float(r["dt_over_estimate"]), y, color=colors[r["outcome"]], s=60, edgecolor="k")
        ax.axvline(1.0, color="0.5", linestyle="--", label="predicted stable step")
        ax.set_xscale("log")
        ax.set_xlabel("time step / predicted stable step C μ h_f / G_eff")
        ax.set_title(f"{scheme.replace('_', '-')} coupling, {steps} steps (drifting runs longer)")
        ax.set_yticks(range(len(scenes)))
        ax.set_yticklabels([f"{f}: {v}" for f, v in scenes], fontsize=8)
        ax.grid(True, alpha=0.3)
    for outcome, color in colors.items():
        axes[1].scatter([], [], color=color, edgecolor="k", label=outcome)
    axes[1].legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    figure.tight_layout()
    figure.savefig(path + ".part.png", dpi=100)
    os.replace(path + ".part.png", path)


if __name__ == "__main__":
    sys.exit(main())
