#!/usr/bin/env python3
"""Writes a fake Moodle "Download all submissions" of a test class, for trying `cg grade` on
what Moodle gives (docs/instructor-guide.md).

The class is the reference solutions handed in through Moodle in every form its download
takes: a Moodle 4.1+ folder (<name>_<ID>_assignsubmission_file) holding a zip, a 3.1-4.0
folder (trailing _) holding loose files, the flat form (<name>_<ID>_assignsubmission_file_<file>),
blind marking ("Participant_<ID>"), Japanese names, and one student.toml that claims another
number than the roster's. Then COUNT more participants, every fifth with a reversed face,
every tenth with an a2 syntax error (as make-test-class.py). It writes FOLDER/download.zip (as
Moodle zips it, UTF-8 names), FOLDER/download/ (the same, unpacked) and FOLDER/roster.csv
(student, name, entry = the participant ID).
Moodle の「すべての提出をダウンロードする」を模したものを、テスト用のクラスから作ります。

    python3 scripts/make-moodle-download.py /tmp/moodle [COUNT]
    cargo run --release -- grade /tmp/moodle/download.zip --roster /tmp/moodle/roster.csv \\
        --out /tmp/moodle/grades --moodle-lang ja
"""
import io
import os
import sys
import zipfile

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "solutions", "src")
MODULES = ["a1", "a2", "a3", "a4", "s"]
REVERSED_FROM = "canonical_faces(&spec.shape).iter().map(|f| f.map(|c| map[c as usize])).collect()"
REVERSED_TO = ("let mut v: Vec<[u32; 3]> = canonical_faces(&spec.shape).iter()"
               ".map(|f| f.map(|c| map[c as usize])).collect(); v[0].swap(1, 2); v")


def six(solutions, student, mistake=None):
    """The six files: name inside exercises/ -> text."""
    files = {f"src/{m}.rs": solutions[m] for m in MODULES}
    if mistake == "reversed":
        files["src/a1.rs"] = files["src/a1.rs"].replace(REVERSED_FROM, REVERSED_TO, 1)
    if mistake == "syntax":
        files["src/a2.rs"] = files["src/a2.rs"].replace("pub fn camera(", "pub fn camera(;", 1)
    files["student.toml"] = f'student = "{student}"\ntable = 1\n'
    return files


def zipped(files):
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as z:
        for name, text in files.items():
            z.writestr(name, text)
    return buf.getvalue()


def upload(files, kind):
    """What the student uploaded: file name (inside the participant's folder) -> bytes."""
    if kind == "zip":
        return {"handin.zip": zipped({f"handin/exercises/{n}": t for n, t in files.items()})}
    if kind == "tree":
        return {f"exercises/{n}": t.encode() for n, t in files.items()}
    # Loose files: a1.rs ... s.rs and student.toml.
    return {os.path.basename(n): t.encode() for n, t in files.items()}


def main() -> None:
    if len(sys.argv) not in (2, 3):
        sys.exit("usage: make-moodle-download.py FOLDER [COUNT]")
    out, count = sys.argv[1], int(sys.argv[2]) if len(sys.argv) == 3 else 0
    solutions = {m: open(os.path.join(ROOT, f"{m}.rs"), encoding="utf-8").read() for m in MODULES}
    if REVERSED_FROM not in solutions["a1"]:
        sys.exit("solutions/src/a1.rs changed: update REVERSED_FROM")
    # (name, participant ID, form, upload, number in student.toml, roster's number, mistake)
    people = [
        ("山田 太郎", 1001, "4.1", "zip", "20260001", "20260001", None),
        ("Jane Roe", 1002, "3.1", "loose", "20260002", "20260002", "reversed"),
        ("John Smith", 1003, "flat", "zip", "20260003", "20260003", "syntax"),
        ("Participant", 1004, "4.1", "tree", "20260004", "20260004", None),
        ("鈴木 花子", 1006, "4.1", "zip", "20260099", "20260006", None),
    ]
    for i in range(count):
        mistake = "reversed" if i % 5 == 1 else "syntax" if i % 10 == 3 else None
        form = ["4.1", "3.1", "flat"][i % 3]
        kind = ["zip", "loose", "tree"][i % 3] if form != "flat" else "zip"
        number = f"2027{i:04d}"
        people.append((f"Student {i:03d}", 2000 + i, form, kind, number, number, mistake))
    items = {}
    roster = ["student,name,entry"]
    for name, pid, form, kind, claims, number, mistake in people:
        prefix = f"{name}_{pid}_assignsubmission_file"
        for fname, data in upload(six(solutions, claims, mistake), kind).items():
            if form == "4.1":
                items[f"{prefix}/{fname}"] = data
            elif form == "3.1":
                items[f"{prefix}_/{fname}"] = data
            else:
                items[f"{prefix}_{fname}"] = data
        roster.append(f"{number},{name if name != 'Participant' else 'Blind Student'},{pid}")
    os.makedirs(out, exist_ok=True)
    with zipfile.ZipFile(os.path.join(out, "download.zip"), "w", zipfile.ZIP_DEFLATED) as z:
        for name, data in items.items():
            z.writestr(name, data)
    for name, data in items.items():
        path = os.path.join(out, "download", name)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "wb") as f:
            f.write(data)
    with open(os.path.join(out, "roster.csv"), "w", encoding="utf-8") as f:
        f.write("\n".join(roster) + "\n")
    print(f"{len(people)} participants in {out}/download.zip, {out}/download/, {out}/roster.csv")


if __name__ == "__main__":
    main()
