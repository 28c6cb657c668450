#!/usr/bin/env bash
# The Python package (crates/afsv-py, docs/python.md) in CI, right after `cargo test
# --workspace --release`: a virtual environment under target/, the extension module from
# that build (no second compile), pytest against the CLI binary, and every ```python block
# of docs/python.md as a script.
#
# Why not `maturin develop` here: maturin builds `-p afsv-py` alone, whose feature
# resolution differs from the workspace's (the test build turns on dev-dependency
# features; PyO3's macros turn on more `syn` features), so it recompiles the whole
# dependency tree: 4-5 min on the 2-core machine instead of seconds. The cdylib of the
# workspace build is the same code; it is laid out as `maturin develop` lays it (the module
# beside the Python sources, a .pth file in the venv). `AFSV_PY_MATURIN=1` builds and
# installs the real wheel with maturin instead (the user's `pip install ./crates/afsv-py`).
set -euo pipefail
cd "$(dirname "$0")/.."
root="$PWD"
venv="$root/target/py-venv"
if [ ! -x "$venv/bin/python" ]; then
    python3 -m venv "$venv"
fi
"$venv/bin/pip" install --quiet --disable-pip-version-check numpy pytest
if [ "${AFSV_PY_MATURIN:-0}" = 1 ]; then
    "$venv/bin/pip" install --quiet --disable-pip-version-check maturin
    (cd crates/afsv-py && VIRTUAL_ENV="$venv" "$venv/bin/maturin" develop --release --quiet)
else
    so="$(cargo test --workspace --release --no-run --message-format=json 2>/dev/null \
        | "$venv/bin/python" -c '
import json, sys
found = []
for line in sys.stdin:  # read to the end: cargo must not meet a closed pipe
    try:
        m = json.loads(line)
    except ValueError:
        continue
    if m.get("reason") == "compiler-artifact" and m["target"]["name"] == "_afsv" and "cdylib" in m["target"]["kind"]:
        found += [f for f in m["filenames"] if f.endswith(".so")]
print(found[0] if found else "")
')"
    if [ -z "$so" ] || [ ! -f "$so" ]; then
        echo "python-test: no extension module from the workspace build" >&2
        exit 1
    fi
    cp "$so" crates/afsv-py/python/afsv/_afsv.abi3.so
    site="$("$venv/bin/python" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')"
    echo "$root/crates/afsv-py/python" > "$site/afsv-dev.pth"
fi
# AFSV_PY_SLOW=1 adds the tests marked slow (the Chapter 6 GA against the CLI, about
# 75 s of CPU) and the docs' slow blocks; CI runs without it.
AFSV_BIN="$root/target/release/afsv" "$venv/bin/python" -m pytest -q crates/afsv-py/tests
# The docs' examples, each block in a scratch folder; a block fenced ```python slow (a GA
# run, a minute or more) runs only with AFSV_PY_SLOW=1, as the slow tests do.
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
"$venv/bin/python" - "$root/docs/python.md" "$scratch" <<'PY'
import os, pathlib, re, subprocess, sys
doc, scratch = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
kinds = r"python|python slow" if os.environ.get("AFSV_PY_SLOW") == "1" else r"python"
blocks = re.findall(rf"```(?:{kinds})\n(.*?)```", doc.read_text(), re.S)
if not blocks:
    sys.exit(f"{doc}: no python block")
for i, code in enumerate(blocks, 1):
    script = scratch / f"block{i}.py"
    script.write_text(code)
    subprocess.run([sys.executable, str(script)], cwd=scratch, check=True)
print(f"docs/python.md: {len(blocks)} python blocks ran")
PY
