#!/usr/bin/env python3
"""The C test programs of c_tests/CMakeLists.txt for the given configuration
folders, one a line: "<name> <config folder> <defines> <sources...>"
(defines comma-separated, "-" for none; sources relative to c_tests/).

    c_tests.py c_tests/CMakeLists.txt cfg cfg_manual

Reads cop_add_library (library -> folder), cop_add_sim (sim -> library),
set(<var> ...) lists, cop_test_program and target_compile_definitions, so
that the target runs build each test exactly as CTest does.
"""
import re
import sys


def main():
    path, wanted = sys.argv[1], set(sys.argv[2:])
    text = open(path).read()
    libs = dict(re.findall(r'cop_add_library\((\w+) "\$\{CMAKE_CURRENT_SOURCE_DIR\}/(\w+)"\)', text))
    sims = dict(re.findall(r"cop_add_sim\((\w+) (\w+)\)", text))
    variables = {k: v.split() for k, v in re.findall(r"set\((\w+_sources) ([^)]*)\)", text)}
    defines = {}
    for name, defs in re.findall(r"target_compile_definitions\((\w+) PRIVATE ([^)]*)\)", text):
        defines.setdefault(name, []).extend(defs.split())
    for name, sim, srcs in re.findall(r"^cop_test_program\((\w+) (\w+) ([^)]*)\)", text, re.M):
        cfg = libs.get(sims.get(sim, ""), "")
        if cfg not in wanted:
            continue
        files = []
        for s in srcs.split():
            m = re.match(r"\$\{(\w+)\}$", s)
            files += variables[m.group(1)] if m else [s]
        print(name, "c_tests/" + cfg, ",".join(defines.get(name, [])) or "-", " ".join(files))


if __name__ == "__main__":
    main()
