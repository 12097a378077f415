#!/usr/bin/python3
"""Writes the PNG files the reader's tests use (tests/files/pngs/), byte for byte the same at every
run: one small picture in every valid encoding the reader must read identically (8 and 16 bits,
grey, grey with alpha, RGB, RGBA, palette with and without tRNS, 1-, 2- and 4-bit palettes,
Adam7-interlaced, IDAT split into 1-byte chunks, a tEXt chunk), and one malformed file for each
way a PNG from elsewhere has been seen to break a reader (README.md in that folder lists them).
Hand-written with zlib, so every byte is chosen here.

With --encodings-of, it instead writes one 8-bit RGBA PNG (as twinraster renders them) again in
every encoding that can hold it: the image path's fuzzing seeds (scripts/fuzz.sh).

Usage: make-test-pngs.py --out DIR
       make-test-pngs.py --encodings-of RENDER.png --out DIR"""
import argparse
import os
import struct
import zlib

W, H = 13, 7  # odd sizes, so that Adam7's passes and sub-byte rows have ragged ends


def picture():
    """RGBA8 rows of the reference picture: four colours in bands, a transparent corner."""
    colours = [(255, 0, 0, 255), (0, 128, 255, 255), (20, 200, 60, 255), (255, 255, 255, 0)]
    return [[colours[(x // 4 + y // 3) % 4] for x in range(W)] for y in range(H)]


def chunk(kind, data, crc=None):
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) if crc is None else crc)


def ihdr(width, height, depth, colour, interlace=0):
    return chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, depth, colour, 0, 0, interlace))


SIGNATURE = b"\x89PNG\r\n\x1a\n"


def png(header, idat_data, extra_before=b"", split=None, end=True):
    """A file from its chunks: IDAT whole, or split into pieces of `split` bytes."""
    pieces = [idat_data] if split is None else [idat_data[i:i + split] for i in range(0, len(idat_data), split)]
    return SIGNATURE + header + extra_before + b"".join(chunk(b"IDAT", p) for p in pieces) + (chunk(b"IEND", b"") if end else b"")


def pack(samples, depth):
    """One row of samples at `depth` bits, most significant first, padded to a byte."""
    if depth >= 8:
        return b"".join(s.to_bytes(depth // 8, "big") for s in samples)
    out, bits, acc = bytearray(), 0, 0
    for s in samples:
        acc, bits = (acc << depth) | s, bits + depth
        if bits == 8:
            out.append(acc)
            acc, bits = 0, 0
    if bits:
        out.append(acc << (8 - bits))
    return bytes(out)


ADAM7 = [(0, 0, 8, 8), (4, 0, 8, 8), (0, 4, 4, 8), (2, 0, 4, 4), (0, 2, 2, 4), (1, 0, 2, 2), (0, 1, 1, 2)]


CHANNELS = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}  # samples per pixel of each PNG colour type


def scanlines(rows, depth, interlace, channels=1):
    """Filter type 0 scanlines of sample rows, in Adam7 order when interlaced."""
    if not interlace:
        return b"".join(b"\0" + pack(r, depth) for r in rows)
    out = b""
    for x0, y0, dx, dy in ADAM7:
        for y in range(y0, H, dy):
            pixels = [rows[y][x * channels:(x + 1) * channels] for x in range(x0, W, dx)]
            if pixels:
                out += b"\0" + pack([s for p in pixels for s in p], depth)
    return out


def encoded(rows, depth, colour, interlace=0, extra=b"", split=None):
    data = scanlines(rows, depth, interlace, CHANNELS[colour])
    return png(ihdr(W, H, depth, colour, interlace), zlib.compress(data, 9), extra, split)


def per_pixel(pixel_to_samples):
    """The picture's rows as flat samples, each pixel turned into its samples by the function."""
    return [[s for p in row for s in pixel_to_samples(p)] for row in picture()]


def valid_files():
    """The picture (or its grey version) in every encoding; each reads as the same RGBA."""
    files = {}
    files["rgba8.png"] = encoded(per_pixel(lambda p: p), 8, 6)
    files["rgba16.png"] = encoded(per_pixel(lambda p: [v * 257 for v in p]), 16, 6)
    opaque = [[(r, g, b, 255) for r, g, b, _ in row] for row in picture()]
    files["rgb8.png"] = encoded([[s for p in row for s in p[:3]] for row in opaque], 8, 2)
    files["rgb16.png"] = encoded([[s * 257 for p in row for s in p[:3]] for row in opaque], 16, 2)
    files["rgba8-interlaced.png"] = encoded(per_pixel(lambda p: p), 8, 6, interlace=1)
    files["rgba8-1-byte-idats.png"] = encoded(per_pixel(lambda p: p), 8, 6, split=1)
    # An empty IDAT before the data is valid (stb_image copied from a null pointer there).
    files["rgba8-empty-first-idat.png"] = (SIGNATURE + ihdr(W, H, 8, 6) + chunk(b"IDAT", b"")
                                           + chunk(b"IDAT", zlib.compress(scanlines(per_pixel(lambda p: p), 8, False), 9))
                                           + chunk(b"IEND", b""))
    files["rgba8-text.png"] = encoded(per_pixel(lambda p: p), 8, 6, extra=chunk(b"tEXt", b"Comment\0made by make-test-pngs.py"))
    palette = [(255, 0, 0), (0, 128, 255), (20, 200, 60), (255, 255, 255)]
    index = {c: i for i, c in enumerate(palette)}
    indices = [[index[p[:3]] for p in row] for row in picture()]
    plte = chunk(b"PLTE", b"".join(bytes(c) for c in palette))
    trns = chunk(b"tRNS", bytes([255, 255, 255, 0]))
    for depth in (2, 4, 8):
        files["palette%d.png" % depth] = encoded(indices, depth, 3, extra=plte + trns)
    files["palette8-interlaced.png"] = encoded(indices, 8, 3, interlace=1, extra=plte + trns)
    # Grey: a picture of its own (grey levels of the bands), 1 to 16 bits, with and without alpha.
    levels = {1: [0, 1, 0, 1], 2: [0, 1, 2, 3], 4: [0, 5, 10, 15], 8: [0, 85, 170, 255], 16: [0, 21845, 43690, 65535]}
    for depth, values in levels.items():
        rows = [[values[(x // 4 + y // 3) % 4] for x in range(W)] for y in range(H)]
        files["grey%d.png" % depth] = encoded(rows, depth, 0)
        files["grey%d-interlaced.png" % depth] = encoded(rows, depth, 0, interlace=1)
    ga = [[s for x in range(W) for s in (levels[8][(x // 4 + y // 3) % 4], 255 - 40 * (x % 3))] for y in range(H)]
    files["grey-alpha8.png"] = encoded(ga, 8, 4)
    files["grey-alpha16.png"] = encoded([[v * 257 for v in row] for row in ga], 16, 4)
    files["grey-alpha8-interlaced.png"] = encoded(ga, 8, 4, interlace=1)
    files["rgb8-interlaced.png"] = encoded([[s for p in row for s in p[:3]] for row in opaque], 8, 2, interlace=1)
    files["rgba16-interlaced.png"] = encoded(per_pixel(lambda p: [v * 257 for v in p]), 16, 6, interlace=1)
    return files


def malformed_files():
    """One file per way of breaking a reader; each must be refused with a reason."""
    good_rows = per_pixel(lambda p: p)
    good_idat = zlib.compress(scanlines(good_rows, 8, False), 9)
    header = ihdr(W, H, 8, 6)
    files = {}
    # A deflate block of the reserved type 3 (stb_image: an error without a reason).
    files["deflate-reserved-block.png"] = png(header, b"\x78\x01" + b"\x07" + b"\0" * 8)
    # An IDAT that says it is longer than 2^31 bytes, followed by nothing.
    files["idat-length-over-2-31.png"] = SIGNATURE + header + struct.pack(">I", 0x80000001) + b"IDAT" + b"\0" * 16
    # Sides no canvas can have: 1,000,000 x 1,000,000 (a decompression bomb's header).
    files["side-over-limit.png"] = png(ihdr(1_000_000, 1_000_000, 1, 0), zlib.compress(b"\0" * 4096, 9))
    # 16384 x 16384 1-bit grey, all zero rows, compressed to a few kilobytes: a real image, but
    # 1 GiB of RGBA; its IDAT is cut short, so it ends before its last row.
    bomb = zlib.compress(b"\0" * (16384 * (1 + 2048)), 9)
    files["bomb-16384-truncated.png"] = png(ihdr(16384, 16384, 1, 0), bomb[: len(bomb) // 2])
    # Checksums: IHDR's CRC, IDAT's CRC, zlib's Adler-32.
    files["ihdr-bad-crc.png"] = SIGNATURE + chunk(b"IHDR", header[8:-4], crc=0) + chunk(b"IDAT", good_idat) + chunk(b"IEND", b"")
    files["idat-bad-crc.png"] = SIGNATURE + header + chunk(b"IDAT", good_idat, crc=0x12345678) + chunk(b"IEND", b"")
    files["bad-adler32.png"] = png(header, good_idat[:-4] + bytes(b ^ 0xFF for b in good_idat[-4:]))
    # A palette of 2 colours, and pixels that use index 3.
    files["palette-index-out-of-range.png"] = png(
        ihdr(W, H, 8, 3), zlib.compress(scanlines([[3 if x == 5 else x % 2 for x in range(W)] for _ in range(H)], 8, False)),
        chunk(b"PLTE", bytes([0, 0, 0, 255, 255, 255])))
    # The same bad Adler-32 in 1-byte IDATs: libspng stops at the last row, before the checksum.
    files["bad-adler32-split.png"] = png(header, good_idat[:-4] + bytes(b ^ 0xFF for b in good_idat[-4:]), split=1)
    # Bytes after the end of the zlib stream, in an IDAT of their own.
    files["data-after-zlib-stream.png"] = png(header, good_idat + b"junk", split=len(good_idat))
    # A 1-bit palette of one colour, interlaced, with index 1 only at the last pixel, which Adam7's
    # fifth pass carries at the ragged end of its row.
    last = [[1 if (x, y) == (W - 1, H - 1) else 0 for x in range(W)] for y in range(H)]
    files["palette1-interlaced-index-out-of-range.png"] = png(
        ihdr(W, H, 1, 3, 1), zlib.compress(scanlines(last, 1, True), 9), chunk(b"PLTE", bytes([10, 20, 30])))
    # A compressed text chunk that inflates to 16 MiB (a bomb in an ancillary chunk).
    files["ztxt-bomb.png"] = png(header, good_idat, chunk(b"zTXt", b"Comment\0\0" + zlib.compress(b"x" * (16 << 20), 9)))
    # An unknown chunk whose type holds ESC: never echoed to the terminal.
    files["chunk-type-with-escape.png"] = png(header, good_idat, chunk(b"a\x1b[1", b"\x1b[31mred"))
    files["empty-first-idat-only.png"] = SIGNATURE + header + chunk(b"IDAT", b"") + chunk(b"IEND", b"")
    # Cut off: in the middle of IDAT, and before IEND.
    whole = png(header, good_idat)
    files["truncated-in-idat.png"] = whole[: len(SIGNATURE) + len(header) + 8 + len(good_idat) // 2]
    files["no-iend.png"] = png(header, good_idat, end=False)
    files["not-a-png.png"] = b"GIF89a this is not a PNG at all"
    files["empty.png"] = b""
    files["signature-only.png"] = SIGNATURE
    # A filter type that does not exist (5) on the first row.
    bad_filter = bytearray(scanlines(good_rows, 8, False))
    bad_filter[0] = 5
    files["bad-filter-type.png"] = png(header, zlib.compress(bytes(bad_filter), 9))
    # Image data that ends a row early (too few bytes for 7 rows of 13 pixels).
    files["too-little-data.png"] = png(header, zlib.compress(scanlines(good_rows, 8, False)[:100], 9))
    # Headers no PNG has, each followed by image data that would otherwise read: a colour type that
    # does not exist (5), a bit depth that does not exist (7), one the colour type does not allow.
    files["ihdr-colour-type-5.png"] = png(ihdr(W, H, 8, 5), good_idat)
    files["ihdr-bit-depth-7.png"] = png(ihdr(W, H, 7, 6), good_idat)
    files["ihdr-palette-16-bit.png"] = png(ihdr(W, H, 16, 3), good_idat, chunk(b"PLTE", bytes([0, 0, 0])))
    # Cut off inside a header whose colour type is already wrong: the colour type is named, from a
    # file as from memory.
    files["ihdr-cut-after-colour-type-5.png"] = SIGNATURE + ihdr(W, H, 8, 5)[:8 + 10]
    # A text chunk that says it runs past the end of the file.
    files["text-past-the-end.png"] = SIGNATURE + header + struct.pack(">I", 4096) + b"tEXtComment\0cut"
    return files


def large_files():
    """Valid files that declare far more pixels than their bytes: what a reader must not hold whole."""
    # 16384 x 16384 1-bit grey, all zero rows: 32 KB of file, 1 GiB as RGBA.
    rows = zlib.compress(b"\0" * (16384 * (1 + 2048)), 9)
    # Interlaced, 8192 x 4097 1-bit grey: one row over 2^25 pixels, what compare holds whole.
    w, h, interlaced = 8192, 4097, 0
    for x0, y0, dx, dy in ADAM7:
        pw, ph = max(0, -(-(w - x0) // dx)), max(0, -(-(h - y0) // dy))
        interlaced += ph * (1 + -(-pw // 8)) if pw and ph else 0
    return {"declares-16384x16384.png": png(ihdr(16384, 16384, 1, 0), rows),
            "interlaced-8192x4097.png": png(ihdr(w, h, 1, 0, 1), zlib.compress(b"\0" * interlaced, 9))}


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    return a if pa <= pb and pa <= pc else (b if pb <= pc else c)


def read_rgba8(data):
    """The rows of a non-interlaced 8-bit RGBA PNG (twinraster's own output), as pixel tuples."""
    assert data[:8] == SIGNATURE, "not a PNG"
    pos, idat, size = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert (depth, colour, interlace) == (8, 6, 0), "only twinraster's own 8-bit RGBA PNGs"
            size = (width, height)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height = size
    raw, stride, rows, prev = zlib.decompress(idat), width * 4, [], bytearray(width * 4)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - 4] if i >= 4 else 0
            b, c = prev[i], (prev[i - 4] if i >= 4 else 0)
            line[i] = (line[i] + (0, a, b, (a + b) // 2, paeth(a, b, c))[kind]) & 255
        rows.append([tuple(line[x * 4:x * 4 + 4]) for x in range(width)])
        prev = line
    return rows


def encodings_of(rows):
    """The picture in rows again: 8 and 16 bits, RGB when opaque, a palette when it has at most 256
    colours, interlaced, and with 1-byte IDATs."""
    global W, H  # the encoders above draw at the module's picture size: now this one's
    H, W = len(rows), len(rows[0])
    flat = [[s for p in row for s in p] for row in rows]
    files = {"rgba8.png": encoded(flat, 8, 6), "rgba16.png": encoded([[v * 257 for v in r] for r in flat], 16, 6),
             "rgba8-interlaced.png": encoded(flat, 8, 6, interlace=1), "rgba8-1-byte-idats.png": encoded(flat, 8, 6, split=1)}
    if all(p[3] == 255 for row in rows for p in row):
        rgb = [[s for p in row for s in p[:3]] for row in rows]
        files["rgb8.png"] = encoded(rgb, 8, 2)
        files["rgb8-interlaced.png"] = encoded(rgb, 8, 2, interlace=1)
    colours = sorted({p for row in rows for p in row})
    if len(colours) <= 256:
        index = {c: i for i, c in enumerate(colours)}
        extra = chunk(b"PLTE", b"".join(bytes(c[:3]) for c in colours)) + chunk(b"tRNS", bytes(c[3] for c in colours))
        indices = [[index[p] for p in row] for row in rows]
        files["palette8.png"] = encoded(indices, 8, 3, extra=extra)
        files["palette8-interlaced.png"] = encoded(indices, 8, 3, interlace=1, extra=extra)
    return files


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", required=True)
    parser.add_argument("--encodings-of", help="an 8-bit RGBA PNG to write again in every encoding")
    a = parser.parse_args()
    if a.encodings_of:
        os.makedirs(a.out, exist_ok=True)
        for name, data in sorted(encodings_of(read_rgba8(open(a.encodings_of, "rb").read())).items()):
            with open(os.path.join(a.out, name), "wb") as f:
                f.write(data)
        return
    for sub, files in (("valid", valid_files()), ("malformed", malformed_files()), ("large", large_files())):
        os.makedirs(os.path.join(a.out, sub), exist_ok=True)
        for name, data in sorted(files.items()):
            with open(os.path.join(a.out, sub, name), "wb") as f:
                f.write(data)


if __name__ == "__main__":
    main()
