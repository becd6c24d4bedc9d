#!/usr/bin/env bash
# The kit's test command (README): set up what the tests need, then run every test of the
# workspace. キットのテスト: 必要なものを準備してから、ワークスペースの全テストを実行します。
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cargo test --workspace --locked "$@"
