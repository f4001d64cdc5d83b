#!/usr/bin/env python3
"""Field layout of named types from rustc's `-Zprint-type-sizes` output.

usage: type_layout.py <print-type-sizes output> <type> [<type>[@<variant>] ...]

rustc prints every type whose layout it computed, fields in memory order
with the padding between them, e.g.

    print-type-size type: `srdo::Slot`: 32 bytes, alignment: 4 bytes
    print-type-size     field `.held`: 8 bytes
    print-type-size     end padding: 2 bytes

For an enum, `<type>@<variant>` selects the fields of one variant; the
enum alone gives one `variant <name>` line per variant with its size. Output, one line per
field and per padding: `<type>\t<field>\t<offset>\t<bytes>`, offsets
summed in memory order from the start of the type (the variant); then a
`<type>\t(size)\t\t<size of the type>` line. Fails when a type is missing
or its fields and padding do not add up to its size.
"""

import re
import sys

HEAD = re.compile(r"^print-type-size type: `(.+)`: (\d+) bytes, alignment: (\d+) bytes")
VARIANT = re.compile(r"^print-type-size {5}variant `(.+)`: (\d+) bytes")
FIELD = re.compile(r"^print-type-size( +)field `\.?(.+)`: (\d+) bytes")
PAD = re.compile(r"^print-type-size( +)((?:end )?padding): (\d+) bytes")


def parse(lines):
    """{type: (size, {variant or None: [(name, bytes)]})}; a variant's own
    size is the entry `variant <name>` of the None list."""
    types = {}
    current = None
    variant = None
    for line in lines:
        m = HEAD.match(line)
        if m:
            # The same type may be printed more than once; the first wins.
            current = None if m.group(1) in types else m.group(1)
            if current:
                types[current] = (int(m.group(2)), {None: []})
            variant = None
            continue
        if current is None:
            continue
        m = VARIANT.match(line)
        if m:
            variant = m.group(1)
            types[current][1][variant] = []
            types[current][1][None].append((f"variant {variant}", int(m.group(2))))
            continue
        m = FIELD.match(line) or PAD.match(line)
        if m:
            # Fields of a variant are indented deeper than the variant line.
            depth = len(m.group(1))
            key = variant if variant is not None and depth > 5 else None
            types[current][1][key].append((m.group(2), int(m.group(3))))
    return types


def main():
    if len(sys.argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    with open(sys.argv[1], encoding="utf-8") as f:
        types = parse(f)
    for spec in sys.argv[2:]:
        name, _, variant = spec.partition("@")
        if name not in types:
            print(f"type_layout.py: no layout of `{name}` in {sys.argv[1]}", file=sys.stderr)
            return 1
        size, parts = types[name]
        fields = parts.get(variant or None)
        if fields is None:
            print(f"type_layout.py: `{name}` has no variant `{variant}`", file=sys.stderr)
            return 1
        enum = not variant and len(parts) > 1
        offset = 0
        for field, n in fields:
            print(f"{spec}\t{field}\t{0 if enum else offset}\t{n}")
            offset = max(offset, n) if enum else offset + n
        if offset > size or (not variant and not enum and offset != size):
            print(f"type_layout.py: `{spec}`: fields add up to {offset}, size {size}", file=sys.stderr)
            return 1
        if offset < size:
            print(f"{spec}\tend padding\t{offset}\t{size - offset}")
        print(f"{spec}\t(size)\t\t{size}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
