#!/usr/bin/env bash
# Installs what the kit's tests need from the system, idempotently. Safe to run many times.
# キットのテストに必要なシステムのパッケージを入れます（何度実行しても同じ結果になります）。
set -euo pipefail

need_cmd() {
  if ! command -v "$1" >/dev/null 2>&1; then
    echo "setup: '$1' not found. Install Rust with rustup (https://rustup.rs) first." >&2
    echo "setup: '$1' が見つかりません。rustup (https://rustup.rs) で Rust を入れてください。" >&2
    exit 1
  fi
}
need_cmd cargo
need_cmd rustc

# rustfmt and clippy for .ci/run (no-ops when present).
if ! cargo fmt --version >/dev/null 2>&1 || ! cargo clippy --version >/dev/null 2>&1; then
  rustup component add rustfmt clippy
fi

# Debian packages the tests use: a C compiler and Mesa's off-screen OpenGL (OSMesa) for the
# OpenGL reference renderer (crates/glref) that the CPU rasterizer is compared with; LuaLaTeX
# with Japanese support and TikZ, to compile the filled report template (crates/report).
PACKAGES=(
  gcc libc6-dev libosmesa6-dev   # the OpenGL reference (crates/glref): a C compiler and Mesa's OSMesa
  texlive-luatex texlive-lang-japanese texlive-latex-recommended texlive-pictures   # the report template
  mesa-vulkan-drivers libvulkan1   # the GPU renderer (crates/gpu) on Mesa's software Vulkan (lavapipe)
  xvfb xauth xdotool libxkbcommon-x11-0 libx11-xcb1   # the viewer's window test under a virtual display
  weston libwayland-client0 libwayland-cursor0 libxkbcommon0   # the viewer's window on Wayland (weston's headless backend)
  bubblewrap   # the grading sandbox (crates/sandbox): no network, no files outside its folder, nothing to start
)

if ! command -v dpkg-query >/dev/null 2>&1 || ! command -v apt-get >/dev/null 2>&1; then
  echo "setup: not a Debian/Ubuntu system; install these yourself if you want every test to run:" >&2
  echo "setup: Debian/Ubuntu 以外のシステムです。すべてのテストを動かすには次を入れてください:" >&2
  echo "  ${PACKAGES[*]}" >&2
  exit 0
fi

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  if [ "$(id -u)" -ne 0 ]; then SUDO=sudo; else SUDO=; fi
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y --no-install-recommends "${missing[@]}"
fi
