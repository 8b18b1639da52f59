#!/usr/bin/env python3
"""Every public header of include/PCCD has a test (doc/design.md, "Test layout").

A header outside internal/ is covered when a test file is named after it (<Header>_test.cpp
anywhere under test/) or when a test source under test/ includes it by name. Prints each header
without a test and exits 1 if there is any.
Usage: check_header_tests.py <include/PCCD> <test>
"""
import pathlib
import re
import sys


def main(include_root, test_root):
    include_root, test_root = pathlib.Path(include_root), pathlib.Path(test_root)
    headers = sorted(h.relative_to(include_root.parent).as_posix() for h in include_root.rglob("*.h")
                     if "internal" not in h.relative_to(include_root).parts)
    sources = [p for p in test_root.rglob("*") if p.suffix in (".cpp", ".h")]
    if not headers or not sources:
        print(f"no headers under {include_root} or no tests under {test_root}")
        return 1
    named = {p.stem[:-len("_test")] for p in sources if p.stem.endswith("_test")}
    included = set()
    for p in sources:
        included.update(re.findall(r"^\s*#\s*include\s*<(PCCD/[^>]+)>", p.read_text(errors="replace"), re.M))
    missing = [h for h in headers if h not in included and pathlib.Path(h).stem not in named]
    for h in missing:
        print(f"{h}: no test is named after it or includes it")
    print(f"{len(headers)} public headers, {len(missing)} without a test")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main(*(sys.argv[1:3] if len(sys.argv) > 2 else ("include/PCCD", "test"))))
