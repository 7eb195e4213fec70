# Shared by the recording measurement scripts (compare-recording.sh,
# measure-host-contention.sh); sourced, not run.

# check_recording_args SCRIPT RUNS SCENE BENCH...: RUNS a positive integer,
# SCENE an existing scene description, every BENCH an executable; otherwise
# an error naming SCRIPT and the value, and exit 2.
check_recording_args() {
  local script=$1 runs=$2 scene=$3 bench
  shift 3
  [[ $runs =~ ^[1-9][0-9]*$ ]] || { echo "$script: RUNS must be a positive integer, got '$runs'" >&2; exit 2; }
  for bench in "$@"; do
    [[ -x "$bench" ]] || { echo "$script: $bench is not an executable" >&2; exit 2; }
  done
  [[ -f "$scene" ]] || { echo "$script: no scene description $scene" >&2; exit 2; }
}

