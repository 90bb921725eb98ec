#!/usr/bin/env bash
# A case driver stopped by SIGTERM names itself in the command that continues the run, so
# that its checks run at the end of the continued run (a stopped run loses nothing, for the
# drivers too): the plasma shear flow's driver, 20 000 steps of 1 ms, is stopped once its first
# checkpoint exists; it must exit 4 and print "<driver> --restart <out>"; that command then
# finishes the run (a few steps later) with exit 0 and the driver's own report.
#   case_driver_stop_and_continue.sh DRIVER OUTPUT_DIR
set -u
driver=$1 out=$2
rm -rf "$out" "$out.err"
"$driver" --out "$out" --threads 1 --no-progress --set time.dt_s=0.001 --set time.end_s=20 \
  --set output.fields=false 2>"$out.err" >/dev/null &
pid=$!
for _ in $(seq 600); do
  [[ -e $out/checkpoints/checkpoint_000000000.h5 ]] && break
  sleep 0.1
done
sleep 0.5
kill -TERM "$pid"
wait "$pid"
status=$?
if [[ $status -ne 4 ]]; then
  echo "the stopped driver exited $status, not 4:"; cat "$out.err"; exit 1
fi
command=$(sed -n 's/^continue with: //p' "$out.err")
if [[ $command != "$driver --restart $out" ]]; then
  echo "the stopped driver says 'continue with: $command', not '$driver --restart $out'"; exit 1
fi
step=$(sed -n 's/^stopped by signal 15 after step \([0-9]*\) .*/\1/p' "$out.err")
end=$(awk -v s="$step" 'BEGIN { printf "%.3f", (s + 3) * 0.001 }')
report=$($command --no-progress --set time.end_s="$end" 2>"$out.err")
status=$?
if [[ $status -ne 0 || $report != *"relative apparent viscosity"* ]]; then
  echo "the continued driver exited $status with the report '$report':"; cat "$out.err"; exit 1
fi
echo "stopped after step $step with '$command'; continued to t = $end s with the driver's report"
rm -rf "$out" "$out.err"
