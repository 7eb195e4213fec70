#!/usr/bin/env bash
# scripts/lsan-retry.sh against a stand-in command: a run that failed only
# because LeakSanitizer's tracer crashed is run again, at most three runs in
# all; a leak report, another failure, or a third tracer crash is passed on.
set -u
retry="$1"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fails=0
check() { if [[ "$2" == "$3" ]]; then echo "ok: $1"; else echo "FAIL: $1: got '$2', want '$3'"; fails=$((fails + 1)); fi; }
# The stand-in: its Nth run (counted in $dir/n) behaves as $dir/run.N says.
cat > "$dir/fake" <<'FAKE'
#!/usr/bin/env bash
d=$(dirname "$0"); n=$(( $(cat "$d/n" 2>/dev/null || echo 0) + 1 )); echo $n > "$d/n"
case "$(cat "$d/run.$n")" in
  ok) echo "frame written"; exit 0 ;;
  tracer) echo "frame written"; echo "Tracer caught signal 11: addr=0x3328" >&2
          echo "==1==LeakSanitizer has encountered a fatal error." >&2; exit 134 ;;
  leak) echo "==1==ERROR: LeakSanitizer: detected memory leaks" >&2
        echo "==1==LeakSanitizer has encountered a fatal error." >&2; exit 23 ;;
  bad) echo "error: bad option" >&2; exit 2 ;;
esac
FAKE
chmod +x "$dir/fake"
scenario() {  # name expected-rc expected-runs run1 [run2 [run3]]
  rm -f "$dir"/n "$dir"/run.*
  local name=$1 rc_want=$2 runs_want=$3; shift 3
  local k=1; for r in "$@"; do echo "$r" > "$dir/run.$k"; k=$((k + 1)); done
  bash "$retry" "$dir/fake" > "$dir/out" 2> "$dir/err"
  check "$name: exit code" "$?" "$rc_want"
  check "$name: runs" "$(cat "$dir/n")" "$runs_want"
}
scenario "a passing run" 0 1 ok
grep -q "frame written" "$dir/out"; check "a passing run: its output" "$?" 0
scenario "a tracer crash, then a pass" 0 2 tracer ok
grep -q "running again" "$dir/err"; check "a tracer crash: said so" "$?" 0
scenario "two tracer crashes, then a pass" 0 3 tracer tracer ok
scenario "a tracer crash, then a leak" 23 2 tracer leak
scenario "a leak" 23 1 leak
scenario "another failure" 2 1 bad
grep -q "bad option" "$dir/err"; check "another failure: its message" "$?" 0
scenario "three tracer crashes" 134 3 tracer tracer tracer
echo "$fails failed"
[[ $fails -eq 0 ]]
