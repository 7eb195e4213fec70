#!/usr/bin/env python3
"""callgrind-per-draw.py FILE [FUNCTION...] [calls:REGEX...]

Instructions per draw in one thread's callgrind output, written by
`valgrind --tool=callgrind --separate-threads=yes
--toggle-collect='drr::SceneImpl::RecordDraws*'` around
drr_scene_record_bench (Docs/Threads.md): the file's total (everything inside
RecordDraws on that thread) and each FUNCTION's inclusive count (from
callgrind_annotate --inclusive=yes, first line naming it), divided by the
calls of ContextImpl::DrawIndexed the file records. A calls:REGEX argument
prints instead the calls per draw of the functions whose names match REGEX
(calls:pthread_mutex_lock: the locks taken per draw).
"""
import re
import subprocess
import sys


def draw_calls(path, pattern=r'ContextImpl::DrawIndexed\b'):
    """Calls recorded in the file of the functions whose names match pattern."""
    names, current, total = {}, None, 0
    with open(path) as f:
        for line in f:
            m = re.match(r'(c?fn)=\((\d+)\)(?: (.*))?', line)
            if m:
                if m.group(3):
                    names[m.group(2)] = m.group(3)
                current = names.get(m.group(2), '') if m.group(1) == 'cfn' else None
                continue
            if line.startswith('calls=') and current is not None:
                if re.search(pattern, current):
                    total += int(line.split('=')[1].split()[0])
                current = None
    return total


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    path = sys.argv[1]
    functions = [a for a in sys.argv[2:] if not a.startswith('calls:')]
    callees = [a.removeprefix('calls:') for a in sys.argv[2:] if a.startswith('calls:')]
    with open(path) as f:
        m = re.search(r'^totals: (\d+)', f.read(), re.M)
    draws = draw_calls(path)
    if not m or draws == 0:
        sys.exit(f'{path}: no totals line or no DrawIndexed calls')
    print(f'{path}: {draws} draws, {int(m.group(1)) / draws:.0f} instructions per draw in RecordDraws')
    for pattern in callees:
        print(f'  calls of {pattern}: {draw_calls(path, pattern) / draws:.3f} per draw')
    if functions:
        annotated = subprocess.run(['callgrind_annotate', '--inclusive=yes', path],
                                   capture_output=True, text=True, check=True).stdout.splitlines()
        for name in functions:
            counted = (re.match(r'\s*([\d,]+) ', l) for l in annotated if name in l and '=>' not in l)
            first = next((m for m in counted if m), None)
            count = int(first.group(1).replace(',', '')) if first else 0
            print(f'  {name}: {count / draws:.0f} per draw (inclusive)')


if __name__ == '__main__':
    main()
