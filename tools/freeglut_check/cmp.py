# Counts the pixels that differ between two pictures (PNG, 8-bit RGB or RGBA, or binary PPM),
# with no library beyond Python's own (a minimal PNG reader: the five filters, no interlace).
import sys, zlib, struct
def png(path):
    d = open(path, 'rb').read(); pos = 8; idat = b''; w = h = 0
    while pos < len(d):
        n, t = struct.unpack('>I4s', d[pos:pos+8]); c = d[pos+8:pos+8+n]; pos += 12 + n
        if t == b'IHDR': w, h, bd, ct = struct.unpack('>IIBB', c[:10]); ch = {2: 3, 6: 4}[ct]
        if t == b'IDAT': idat += c
    raw = zlib.decompress(idat); stride = w * ch; out = []; prev = bytearray(stride); i = 0
    for y in range(h):
        f = raw[i]; row = bytearray(raw[i+1:i+1+stride]); i += 1 + stride
        for x in range(stride):
            a = row[x-ch] if x >= ch else 0; b = prev[x]; cc = prev[x-ch] if x >= ch else 0
            if f == 1: row[x] = (row[x] + a) & 255
            elif f == 2: row[x] = (row[x] + b) & 255
            elif f == 3: row[x] = (row[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - cc; pa, pb, pc = abs(p-a), abs(p-b), abs(p-cc)
                row[x] = (row[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else cc)) & 255
        out.append(bytes(row[k] for x in range(w) for k in (x*ch, x*ch+1, x*ch+2))); prev = row
    return w, h, b''.join(out)
def ppm(path):
    d = open(path, 'rb').read(); parts = d.split(maxsplit=4)
    return int(parts[1]), int(parts[2]), parts[4]
def load(p): return png(p) if p.endswith('.png') else ppm(p)
(w1, h1, a), (w2, h2, b) = load(sys.argv[1]), load(sys.argv[2])
assert (w1, h1) == (w2, h2), ((w1, h1), (w2, h2))
diff = sum(1 for i in range(w1*h1) if a[3*i:3*i+3] != b[3*i:3*i+3])
print(f"{diff} of {w1*h1} pixels differ ({100*diff/(w1*h1):.3f}%)")
