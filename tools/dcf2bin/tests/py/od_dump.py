"""Prints every subindex of a DCF/EDS as python-canopen reads it, one line
each: index, subindex, data type, access type, PDO mapping, value in
CANopen byte order as hex (NONE without value). The dcf2bin tests compare
this with their own reading of the same file."""

import sys

import canopen
from canopen.objectdictionary import ODVariable


def emit(v: ODVariable) -> None:
    val = v.value if getattr(v, "value", None) is not None else v.default
    data = "NONE" if val is None else v.encode_raw(val).hex().upper()
    print(f"{v.index:04X} {v.subindex:02X} {v.data_type:04X} {v.access_type} {int(v.pdo_mappable)} {data}")


def main() -> None:
    od = canopen.objectdictionary.import_od(sys.argv[1])
    for index in od:
        obj = od[index]
        if isinstance(obj, ODVariable):
            emit(obj)
        else:
            for sub in obj:
                emit(obj[sub])


if __name__ == "__main__":
    main()
