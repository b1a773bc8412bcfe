#!/usr/bin/env python3
"""Writes the seed corpora of the fuzz targets (fuzz/corpus/) from short recordings of the
virtual lidar. Run by hand when the formats change; the outputs are committed.

    ydscope-cli sim --model G1 --pty /tmp/lidar &
    ydscope-cli record --port /tmp/lidar --out /tmp/g1.ydrec --seconds 0.4
    (the same for G6 and TG30)
    ydscope-cli record --port /tmp/g1 --port /tmp/g6 --port /tmp/tg30 --out /tmp/several.ydrec \
        --seconds 0.3         (three sims at once: format version 2, for the recording target only)
    fuzz/make_seeds.py /tmp/g1.ydrec /tmp/g6.ydrec /tmp/tg30.ydrec /tmp/several.ydrec

The real captures (tests/data/captures) and assets/demo-g6.ydrec are added by scripts/fuzz at run
time instead of being copied here.
"""
import pathlib
import struct
import sys

HERE = pathlib.Path(__file__).resolve().parent
TARGET_OF_MODEL = {"G1": "scan_g1", "G6": "scan_g6", "TG30": "scan_tg"}


def timed_records(data):
    offset = struct.unpack_from("<H", data, 14)[0]
    while offset + 16 <= len(data):
        kind, _flags, _reserved, length, t_ns = struct.unpack_from("<BBHIq", data, offset)
        yield kind, data[offset + 16:offset + 16 + length], t_ns
        offset += 16 + length


def records(data):
    for kind, payload, _t_ns in timed_records(data):
        yield kind, payload


def model_of(data):
    for kind, payload in records(data):
        if kind == 3:
            for line in payload.decode("utf-8", "replace").splitlines():
                if line.startswith("model="):
                    return line[len("model="):]
    raise SystemExit("recording has no model")


def mcap_export_input(data, options):
    """A recording as fuzz_mcap_export reads it: an options byte, then per record its type, a time
    step (cube root of the microseconds since the record before), a u16 length and the payload."""
    out = bytearray([options])
    previous_ns = 0
    for kind, payload, t_ns in timed_records(data):
        step = min(255, round((max(0, t_ns - previous_ns) / 1000) ** (1 / 3)))
        previous_ns += step ** 3 * 1000
        payload = payload[:0xFFFF]
        out += struct.pack("<BBH", kind, step, len(payload)) + payload
    return bytes(out)


def write(target, name, data):
    folder = HERE / "corpus" / target
    folder.mkdir(parents=True, exist_ok=True)
    (folder / name).write_bytes(data)


def main(paths):
    for path in map(pathlib.Path, paths):
        data = path.read_bytes()
        if struct.unpack_from("<H", data, 12)[0] == 2:  # several lidars: their bytes interleave
            write("recording", "sim-several.ydrec", data)
            continue
        model = model_of(data)
        device = b"".join(p for kind, p in records(data) if kind == 1)
        # Scan targets: byte 0 is the chunking (fuzz_input.h), then the stream as the device sent it.
        write(TARGET_OF_MODEL[model], f"sim-{model}-chunks32", b"\x20" + device)
        write(TARGET_OF_MODEL[model], f"sim-{model}-whole", b"\xff" + device)
        # Replies: chunking, junk limit, then the start-up replies and the first scan packets.
        write("replies", f"sim-{model}-startup", b"\x05\x10" + device[:160])
        write("recording", f"sim-{model}.ydrec", data)
        # MCAP export: zstd chunks of 64 << 4 bytes (several per recording), and lz4 of 64 KiB.
        write("mcap_export", f"sim-{model}-zstd", mcap_export_input(data, 1 | (4 << 2)))
        write("mcap_export", f"sim-{model}-lz4", mcap_export_input(data, 2 | (10 << 2)))


if __name__ == "__main__":
    main(sys.argv[1:])
