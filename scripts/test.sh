#!/usr/bin/env bash
# The kit's test command (README): set up what the tests need, then run every test of the
# workspace. キットのテスト: 必要なものを準備してから、ワークスペースの全テストを実行します。
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
# wgpu on Mesa's software Vulkan when no other Vulkan driver is chosen (CI has no GPU).
# GPU のない環境では Mesa のソフトウェア Vulkan（lavapipe）を使います。
LVP=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json
if [ -z "${VK_ICD_FILENAMES:-}${VK_DRIVER_FILES:-}" ] && [ -f "$LVP" ] && [ "${CG_REAL_GPU:-}" != 1 ]; then
  export VK_ICD_FILENAMES="$LVP" VK_DRIVER_FILES="$LVP"
fi
export XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-$(mktemp -d)}"
cargo test --workspace --locked "$@"
