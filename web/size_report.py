#!/usr/bin/env python3
"""Where the bytes of a wasm file go: its sections, and the code section's function bodies grouped by the
crate their (mangled) names come from. Needs the name section (the release build keeps it unless stripped).

Usage: python3 web/size_report.py web/pkg/tiltpad_bg.wasm [top_n]
"""
import re
import sys
from collections import Counter

SECTION = {0: "custom", 1: "type", 2: "import", 3: "function", 4: "table", 5: "memory", 6: "global",
           7: "export", 8: "start", 9: "element", 10: "code", 11: "data", 12: "data count"}


def leb(b, i):
    """An unsigned LEB128 at b[i]: (value, next index)."""
    v = shift = 0
    while True:
        x = b[i]
        i += 1
        v |= (x & 0x7F) << shift
        shift += 7
        if x < 0x80:
            return v, i


def crate_of(name):
    """The crate a Rust symbol (legacy mangling) belongs to; for `<T as Trait>` impls, the crate of T."""
    if name.startswith("_ZN"):
        m = re.match(r"_ZN(\d+)", name)
        first = name[len(m.group(0)):len(m.group(0)) + int(m.group(1))]
        if first.startswith("_$LT$"):
            inner = re.match(r"_\$LT\$(?:\$RF\$|\$u5b\$|mut\$u20\$|\$BP\$|)*([A-Za-z_][A-Za-z0-9_]*)", first)
            return inner.group(1) if inner else "<impl>"
        return first
    if name.startswith("_R"):
        m = re.search(r"C[s\d_]*?(\d+)([a-z_][a-z0-9_]*)", name)
        return m.group(2) if m else "<v0>"
    # Already demangled (`crate::path`, `<crate::Type as Trait>`, `<&mut crate::Type as …>`).
    m = re.match(r"[<&\[(\s]*(?:mut |dyn |const |\*)*([A-Za-z_][A-Za-z0-9_]*)(?:::|$|<)", name)
    return m.group(1) if m else "<other: " + name[:30] + ">"


def main(path, top=25):
    b = open(path, "rb").read()
    assert b[:4] == b"\0asm", "not a wasm file"
    i, sections, bodies, names, imported = 8, Counter(), [], {}, 0
    while i < len(b):
        sid, i = b[i], i + 1
        size, i = leb(b, i)
        end = i + size
        label = SECTION.get(sid, str(sid))
        if sid == 0:
            n, j = leb(b, i)
            cname = b[j:j + n].decode()
            label = "custom: " + cname
            j += n
            if cname == "name":
                while j < end:
                    sub, j = b[j], j + 1
                    sub_size, j = leb(b, j)
                    if sub == 1:
                        count, k = leb(b, j)
                        for _ in range(count):
                            idx, k = leb(b, k)
                            ln, k = leb(b, k)
                            names[idx] = b[k:k + ln].decode(errors="replace")
                            k += ln
                    j += sub_size
        elif sid == 2:
            count, j = leb(b, i)
            for _ in range(count):
                for _ in range(2):
                    ln, j = leb(b, j)
                    j += ln
                kind, j = b[j], j + 1
                if kind == 0:
                    imported += 1
                    _, j = leb(b, j)
                elif kind == 1:
                    j += 1
                    flags, j = b[j], j + 1
                    _, j = leb(b, j)
                    if flags & 1:
                        _, j = leb(b, j)
                elif kind == 2:
                    flags, j = b[j], j + 1
                    _, j = leb(b, j)
                    if flags & 1:
                        _, j = leb(b, j)
                elif kind == 3:
                    j += 2
                else:
                    j += 1
                    _, j = leb(b, j)
        elif sid == 10:
            count, j = leb(b, i)
            for _ in range(count):
                s, j2 = leb(b, j)
                bodies.append(j2 - j + s)
                j = j2 + s
        sections[label] += size
        i = end
    total = len(b)
    print(f"{path}: {total / 1e6:.2f} MB")
    for label, size in sections.most_common():
        print(f"  section {label:28s} {size / 1e6:7.2f} MB  {100 * size / total:5.1f} %")
    crates = Counter()
    for k, size in enumerate(bodies):
        crates[crate_of(names.get(imported + k, "?"))] += size
    code = sum(bodies)
    print(f"code by crate ({len(bodies)} functions, {len(names)} named):")
    for crate, size in crates.most_common(top):
        print(f"  {crate:32s} {size / 1e6:7.3f} MB  {100 * size / code:5.1f} % of code")


if __name__ == "__main__":
    main(sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 25)
