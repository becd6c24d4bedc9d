#!/usr/bin/env python3
"""Writes a generated class of submissions for timing `cg grade` (docs/instructor-guide.md).

Each submission is the reference solutions with a student number of its own; every fifth lists
its first face clockwise (a1), every tenth has a syntax error in a2.rs.
採点時間の計測用に、生成した提出物のクラスを書き出します。

    python3 scripts/make-test-class.py 100 /tmp/class100/subs
    cargo run --release -- grade /tmp/class100/subs --out /tmp/class100/out
"""
import os
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "solutions", "src")
REVERSED_FROM = "canonical_faces(&spec.shape).iter().map(|f| f.map(|c| map[c as usize])).collect()"
REVERSED_TO = ("let mut v: Vec<[u32; 3]> = canonical_faces(&spec.shape).iter()"
               ".map(|f| f.map(|c| map[c as usize])).collect(); v[0].swap(1, 2); v")


def main() -> None:
    if len(sys.argv) != 3:
        sys.exit("usage: make-test-class.py COUNT FOLDER")
    count, out = int(sys.argv[1]), sys.argv[2]
    solutions = {m: open(os.path.join(ROOT, f"{m}.rs"), encoding="utf-8").read()
                 for m in ["a1", "a2", "a3", "a4", "s"]}
    if REVERSED_FROM not in solutions["a1"]:
        sys.exit("solutions/src/a1.rs changed: update REVERSED_FROM")
    for i in range(count):
        src = os.path.join(out, f"{i:03d}", "exercises", "src")
        os.makedirs(src, exist_ok=True)
        files = dict(solutions)
        if i % 5 == 1:
            files["a1"] = files["a1"].replace(REVERSED_FROM, REVERSED_TO, 1)
        if i % 10 == 3:
            files["a2"] = files["a2"].replace("pub fn camera(", "pub fn camera(;", 1)
        for module, text in files.items():
            with open(os.path.join(src, f"{module}.rs"), "w", encoding="utf-8") as f:
                f.write(text)
        with open(os.path.join(out, f"{i:03d}", "exercises", "student.toml"), "w",
                  encoding="utf-8") as f:
            f.write(f'student = "2027{i:04d}"\ntable = 1\n')
    print(f"{count} submissions in {out}")


if __name__ == "__main__":
    main()
