"""Prints every subindex of a DCF/EDS as python-canopen reads it, one line
each: index, subindex, data type, access type, PDO mapping, value in
CANopen byte order as hex (NONE without value, ERR when python-canopen
cannot encode the value it read, - when empty). The dcf2bin tests compare
this with their own reading of the same file.

python-canopen has no encoder for TIME_OF_DAY and TIME_DIFFERENCE; it reads
their values as numbers, printed here as the 48-bit little-endian number
(CiA 301 7.1.6.5/6: milliseconds, 4 reserved bits, days)."""

import logging
import sys

import canopen
from canopen.objectdictionary import ODVariable, datatypes

TIME_TYPES = (datatypes.TIME_OF_DAY, datatypes.TIME_DIFFERENCE)


def emit(v: ODVariable) -> None:
    val = v.value if getattr(v, "value", None) is not None else v.default
    if val is None:
        data = "NONE"
    elif v.data_type in TIME_TYPES:
        data = int(val).to_bytes(6, "little").hex().upper()
    else:
        try:
            data = v.encode_raw(val).hex().upper()
        except (ValueError, UnicodeError):
            # A value python-canopen reads but cannot encode (a
            # VISIBLE_STRING with characters outside ASCII).
            data = "ERR"
    print(f"{v.index:04X} {v.subindex:02X} {v.data_type:04X} {v.access_type} {int(v.pdo_mappable)} {data or '-'}")


def main() -> None:
    # Warnings (unsupported data types) go to stderr, not into the dump.
    logging.basicConfig(stream=sys.stderr, level=logging.WARNING)
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
