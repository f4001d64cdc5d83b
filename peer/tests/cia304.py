"""CiA 304 SRDO checksum, written from its definition (docs: SAFETY_BEHAVIOUR
section 3) and independent of the library: CRC-16 with polynomial 0x1021,
initial value 0, no reflection, no final XOR (CRC-16/XMODEM), over the SRDO
parameters in CANopen (little-endian) byte order."""

import struct


def crc16_xmodem(data, crc=0x0000):
    """Bit by bit, most significant bit first."""
    for byte in data:
        crc ^= byte << 8
        for _ in range(8):
            if crc & 0x8000:
                crc = ((crc << 1) ^ 0x1021) & 0xFFFF
            else:
                crc = (crc << 1) & 0xFFFF
    return crc


def srdo_crc_stream(direction, sct, srvt, cob1, cob2, mapping):
    """The bytes the checksum covers: direction (1), SCT (2), SRVT (1),
    COB-ID 1 (4), COB-ID 2 (4), number of mapping entries (1), then per
    entry its subindex (1) and value (4). The transmission type is not
    included."""
    out = struct.pack("<BHBII", direction, sct, srvt, cob1, cob2)
    out += bytes([len(mapping)])
    for sub, entry in enumerate(mapping, start=1):
        out += struct.pack("<BI", sub, entry)
    return out


def srdo_crc(direction, sct, srvt, cob1, cob2, mapping):
    return crc16_xmodem(srdo_crc_stream(direction, sct, srvt, cob1, cob2, mapping))
