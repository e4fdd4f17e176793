# Sourced by the kill tests: start a sweep, kill it at a moment measured from when its output
# first appears, as SIGKILL would hit a job. Moments measured from the start would drift past
# the run's end on a faster machine (no partial file left to resume) or before its first
# checkpoint on a slower one.

# wait_for_output PID OUT: returns once OUT exists (the first checkpoint published it) or the
# job has ended, 30 s at most.
wait_for_output() {
  local pid="$1" out="$2" i
  for ((i = 0; i < 600; i++)); do
    [ -f "$out" ] && return 0
    kill -0 "$pid" 2>/dev/null || return 0
    sleep 0.05
  done
}

# kill_job PID OUT: SIGKILL the whole job at once (mpirun and every rank writing OUT), and reap it.
kill_job() {
  local pid="$1" out="$2"
  pkill -KILL -P "$pid" 2>/dev/null || true
  kill -KILL "$pid" 2>/dev/null || true
  pkill -KILL -f -- "-o $out" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
}
