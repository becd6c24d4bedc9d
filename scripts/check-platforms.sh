#!/usr/bin/env bash
# The kit compiles for the systems students use: Windows and macOS, Intel and ARM (Linux is the test
# run itself).
# `cargo check` of the whole workspace for each target (no linker needed), and of `cg` as the
# students' copy builds it (without default features); the targets' standard
# libraries are added with rustup, idempotently. Run by CI (.ci/run).
# 学生の使う Windows と macOS 向けにもコンパイルできることを確かめます（CI が実行します）。
set -euo pipefail
cd "$(dirname "$0")/.."
# Intel and ARM Macs: the vertex normals' hand-vectorised kernels exist on x86-64 only, so an ARM
# Mac compiles other code (issue 18).
TARGETS=(x86_64-pc-windows-gnu x86_64-apple-darwin aarch64-apple-darwin)
# `cargo check`, failing on any warning in the kit's own code (dependencies' warnings are capped):
# code that only one platform compiles gets no other lint run.
check() {
  local out
  if ! out=$(cargo check "$@" --locked --target "$target" --quiet 2>&1); then
    echo "$out" >&2
    exit 1
  fi
  if grep -q '^warning' <<<"$out"; then
    echo "$out" >&2
    echo "check-platforms: warnings for $target (cargo check $*)" >&2
    exit 1
  fi
}
for target in "${TARGETS[@]}"; do
  if ! rustup target list --installed | grep -qx "$target"; then
    if ! rustup target add "$target"; then
      echo "check-platforms: could not install the standard library for $target (no network?)." >&2
      echo "check-platforms: $target NOT checked." >&2
      continue
    fi
  fi
  echo "check-platforms: cargo check --workspace --target $target"
  check --workspace
  # The students' copy builds `cg` without its default features (no GPU renderer, no
  # instructors' commands: crates/cli/Cargo.toml), which compiles other code at the seams.
  echo "check-platforms: cargo check -p cg-cli --no-default-features --target $target"
  check -p cg-cli --no-default-features
done
