"""The command line shared by the table generators (gles2-tables.py, tessellation-tables.py):
DATA prints the tables; DATA --write DOC replaces them between the generator's markers in
DOC; DATA --check DOC exits 1 when DOC's tables are not the ones the data gives."""
import sys


def main(argv, usage, tables, begin_marker, end_marker, name):
    if len(argv) not in (2, 4) or (len(argv) == 4 and argv[2] not in ("--write", "--check")):
        sys.exit(usage)
    text = tables(argv[1])
    if len(argv) == 2:
        sys.stdout.write(text)
        return 0
    doc = open(argv[3]).read()
    begin, end = doc.find(begin_marker), doc.find(end_marker)
    if begin < 0 or end < begin:
        sys.exit(f"{name}: no {begin_marker} ... {end_marker} in {argv[3]}")
    new = doc[:begin + len(begin_marker)] + "\n" + text + doc[end:]
    if argv[2] == "--check":
        if new != doc:
            print(f"{name}: {argv[3]} differs from the tables of {argv[1]}")
            return 1
        return 0
    open(argv[3], "w").write(new)
    return 0
