"""Shared fixtures: the repository's cases and the command-line binary the package is compared with."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
CASES = ROOT / "cases"


def cli_binary() -> Path | None:
    """The `tiltpad` binary: $TILTPAD_BIN, else the repository's debug then release build, else PATH."""
    env = os.environ.get("TILTPAD_BIN")
    if env:
        return Path(env)
    for profile in ("debug", "release"):
        p = ROOT / "target" / profile / "tiltpad"
        if p.exists():
            return p
    found = shutil.which("tiltpad")
    return Path(found) if found else None


@pytest.fixture(scope="session")
def cli():
    """Runs the command line: cli(args…) → CompletedProcess (text)."""
    binary = cli_binary()
    if binary is None:
        pytest.skip("no tiltpad binary: build it with `cargo build` (or set TILTPAD_BIN)")

    def run(*args: str, check: bool = True) -> subprocess.CompletedProcess:
        return subprocess.run([str(binary), *args], cwd=ROOT, capture_output=True, text=True, check=check)

    return run


@pytest.fixture(scope="session")
def cli_json(cli, tmp_path_factory):
    """The JSON `tiltpad solve CASE --set … --json` writes."""

    def run(case: str, *sets: str) -> dict:
        out = tmp_path_factory.mktemp("cli") / "out.json"
        args = ["solve", case, "--json", str(out)]
        for s in sets:
            args += ["--set", s]
        cli(*args)
        return json.loads(out.read_text())

    return run


@pytest.fixture
def compressor():
    import tiltpad

    return tiltpad.load_case(str(CASES / "compressor-bearing.toml"))
