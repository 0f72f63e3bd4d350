#!/usr/bin/env python3
"""Bad and extreme inputs across every command of the `tiltpad` binary, each run under a time and memory limit.

Usage (from the repository root, after `cargo build --release`):

    python3 tests/harness/bad_inputs.py --bin target/release/tiltpad [--timeout 60] [--mem-gb 8] [--only WORD,WORD]

Every run is one command line with one bad or extreme input (a `--set` value at and beyond the ends of its
key's range, a malformed argument, an output on top of an input, an unreadable or endless input file, a
rotor too large to allocate, ...). A run counts as

- panic       the program panicked or died from a signal (abort on a failed allocation included);
- nonfinite   NaN or inf appears in anything it printed or wrote;
- silent_ok   it exited 0 where the input can have no computed result (the run is marked `error`);
- hung        it ran into the time limit without having printed anything on standard error (no progress
              and no refusal);
- input_lost  a file given as input changed.

It prints the counts and writes every run (command, exit status, seconds, verdict, first lines of its
standard error) to `OUT/runs.jsonl`.
"""

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

NONFINITE = re.compile(r"(?<![A-Za-z_])(nan|NaN|NAN|-?inf|-?Inf|-?INF|Infinity)(?![A-Za-z_])")

ROOT = Path(__file__).resolve().parents[2]
CASES = ROOT / "cases"


def schema(binary):
    out = subprocess.run([binary, "schema", "--json", "-"], capture_output=True, text=True, timeout=60)
    table = json.loads(out.stdout)
    return table if isinstance(table, list) else table.get("keys", [])


INTERVAL = re.compile(r"^\s*[\[(]\s*([-+0-9.eE]+|−?inf)\s*,\s*([-+0-9.eE]+|inf)\s*[\])]")


def interval(row):
    """The ends of a key's allowed interval (`tiltpad schema --json` writes it as `(0, 10000]`), or None."""
    m = INTERVAL.match(str(row.get("allowed") or ""))
    if not m:
        return None
    ends = []
    for t in m.groups():
        try:
            ends.append(float(t))
        except ValueError:
            ends.append(None)
    return ends


def numeric_values(row):
    """Values at and beyond the ends of a key's allowed range, and non-numbers."""
    vals = ["nan", "inf", "-inf", "abc", '""']
    lo, hi = interval(row) or (None, None)
    for v in (lo, hi):
        if isinstance(v, (int, float)):
            vals.append(repr(v))
    if isinstance(lo, (int, float)):
        vals.append(repr(lo - max(1.0, abs(lo))))
    if isinstance(hi, (int, float)):
        vals.append(repr(hi * 10 + 1))
    vals += ["-1", "0", "1e300"]
    return vals


class Harness:
    def __init__(self, binary, out, timeout, mem_gb, only):
        self.binary = str(Path(binary).resolve())
        self.out = Path(out)
        self.timeout = timeout
        self.mem_kb = int(mem_gb * 1024 * 1024)
        self.only = only
        self.runs = []
        self.work = Path(tempfile.mkdtemp(prefix="tiltpad-bad-"))
        shutil.copytree(CASES, self.work / "cases")
        self.cases = self.work / "cases"

    def run(self, name, args, expect="any", inputs=(), stdin=None):
        """expect: 'error' (no result can be computed), 'ok' (valid), 'any'."""
        if self.only and not any(w in name for w in self.only.split(",")):
            return
        outdir = self.work / "out" / re.sub(r"[^A-Za-z0-9_.-]", "_", name)[:120]
        outdir.mkdir(parents=True, exist_ok=True)
        args = [a.replace("{OUT}", str(outdir)).replace("{C}", str(self.cases)).replace("{W}", str(self.work))
                for a in args]
        before = {p: Path(p).read_bytes() for p in inputs if Path(p).is_file()}
        cmd = f"ulimit -v {self.mem_kb}; exec timeout -s KILL {self.timeout} \"$@\""
        t0 = time.monotonic()
        p = subprocess.run(["bash", "-c", cmd, "run", self.binary] + args, capture_output=True, cwd=outdir,
                           stdin=subprocess.DEVNULL if stdin is None else stdin)
        secs = time.monotonic() - t0
        err = p.stderr.decode("utf-8", "replace")
        so = p.stdout.decode("utf-8", "replace")
        written = ""
        for f in outdir.rglob("*"):
            if f.is_file() and f.stat().st_size < 50_000_000:
                written += f.read_bytes().decode("utf-8", "replace")
        verdicts = []
        rc = p.returncode
        if "panicked at" in err or rc == 101 or rc < 0 and rc != -9 or rc in (134, 139) or "memory allocation" in err:
            verdicts.append("panic")
        if rc == -9 or rc == 137:
            if err.strip() == "":
                verdicts.append("hung")
            else:
                verdicts.append("long_with_output")
        text = so + written
        # numbers only: the error text may quote a bad input back ("nan")
        if NONFINITE.search(text) and rc == 0:
            verdicts.append("nonfinite")
        if expect == "error" and rc == 0:
            verdicts.append("silent_ok")
        if expect == "ok" and rc != 0 and rc not in (-9, 137):
            verdicts.append("failed_valid")
        for path, data in before.items():
            if not Path(path).exists() or Path(path).read_bytes() != data:
                verdicts.append("input_lost")
                Path(path).write_bytes(data)
        rec = {"name": name, "args": args, "rc": rc, "seconds": round(secs, 2), "expect": expect,
               "verdicts": verdicts or ["clean"], "stderr": err[-600:]}
        self.runs.append(rec)
        mark = ",".join(rec["verdicts"])
        print(f"{mark:>16} rc={rc:<4} {secs:6.1f}s  {name}", flush=True)
        shutil.rmtree(outdir, ignore_errors=True)

    # ------------------------------------------------------------------ the inputs

    def set_keys(self):
        rows = schema(self.binary)
        case = "{C}/compressor-bearing.toml"
        for row in rows:
            key = row.get("key", "")
            kind = str(row.get("kind", row.get("type", "")))
            if "[]" in key:
                continue
            if "number" in kind or "integer" in kind or interval(row) is not None:
                for v in numeric_values(row):
                    extra = ["--set", "mesh.fidelity=\"preview\""] if not key.startswith("mesh.") else []
                    self.run(f"set {key}={v}", ["solve", case, "--set", f"{key}={v}"] + extra + ["--json", "r.json"])
            else:
                for v in ['"nonsense"', "1", "nan"]:
                    self.run(f"set {key}={v}", ["solve", case, "--set", f"{key}={v}", "--json", "r.json"])

    def solve_extremes(self):
        c = "{C}/compressor-bearing.toml"
        pv = ["--set", 'mesh.fidelity="preview"']
        cases = {
            "E 1e-6 GPa flexible": ["--set", "bearing.pads.youngs_modulus_gpa=1e-6", "--set", "physics.pad_modes=1"],
            "pad 0.01 mm flexible": ["--set", "bearing.pads.thickness_mm=0.01", "--set", "physics.pad_modes=1"],
            "inject 5000 bar iso": ["--set", "operating.injection_pressure_bar=5000"],
            "inject 5000 bar thd": ["--set", "operating.injection_pressure_bar=5000", "--set", 'thermal.model="thd"'],
            "supply -40 C thd": ["--set", "operating.supply_temperature_c=-40", "--set", 'thermal.model="thd"'],
            "supply -40 C iso": ["--set", "operating.supply_temperature_c=-40"],
            "load 1e9 N": ["--set", "operating.load_n=1e9"],
            "load 0 N": ["--set", "operating.load_n=0"],
            "speed 0": ["--set", "operating.speed_rpm=0"],
            "speed 1e6": ["--set", "operating.speed_rpm=1e6"],
            "clearance 1 um": ["--set", "bearing.assembled_clearance_um=1"],
            "viscosity tiny": ["--set", "lubricant.viscosity_pa_s=1e-9"],
        }
        for name, s in cases.items():
            self.run(f"solve {name}", ["solve", c] + s + pv + ["--json", "r.json"])
        f = "{C}/fillon-a-tehd.toml"
        self.run("solve fillon tehd orifice 5000 bar",
                 ["solve", f, "--set", "bearing.pads.orifice=[{position_frac=0.5,diameter_mm=2,length_mm=5}]",
                  "--set", "operating.injection_pressure_bar=5000"] + pv + ["--json", "r.json"])
        for fid in ["preview", "standard"]:
            self.run(f"solve every case {fid}", ["solve", "{C}/test-rig.toml", "--set", f'mesh.fidelity="{fid}"'],
                     expect="ok")

    def files(self):
        w = self.work
        (w / "empty.toml").write_text("")
        (w / "garbage.toml").write_bytes(os.urandom(4096))
        (w / "deep.toml").write_text("a = " + "[" * 100000 + "]" * 100000 + "\n")
        (w / "big.toml").write_text("# " + "x" * (40 * 1024 * 1024) + "\n")
        (w / "dir.toml").mkdir(exist_ok=True)
        os.symlink(self.cases / "compressor-bearing.toml", w / "link.toml")
        for cmd in ["solve", "coefficients", "modes", "frf"]:
            for name, path in [("missing", "{W}/nope.toml"), ("empty", "{W}/empty.toml"),
                               ("garbage", "{W}/garbage.toml"), ("deep", "{W}/deep.toml"), ("big", "{W}/big.toml"),
                               ("dir", "{W}/dir.toml"), ("dev-zero", "/dev/zero"), ("dev-null", "/dev/null")]:
                self.run(f"{cmd} file {name}", [cmd, path], expect="error")
        for name, path in [("dev-zero", "/dev/zero"), ("garbage", "{W}/garbage.toml"), ("dir", "{W}/dir.toml")]:
            self.run(f"rotor file {name}", ["rotor", path, "--speeds", "1000:2000:3"], expect="error")
            self.run(f"sweep file {name}", ["sweep", path, "--vary", "operating.speed_rpm=1000:2000:2"], expect="error")
            self.run(f"batch designs {name}", ["batch", path, "--case", "{C}/compressor-bearing.toml"], expect="error")
            self.run(f"batch case {name}", ["batch", "{C}/designs-compressor.csv", "--case", path], expect="error")

    def outputs(self):
        c = "{C}/compressor-bearing.toml"
        pv = ["--set", 'mesh.fidelity="preview"']
        case_path = str(self.cases / "compressor-bearing.toml")
        self.run("solve json onto its case", ["solve", c, "--json", c] + pv, expect="error", inputs=[case_path])
        self.run("solve vtu onto its case", ["solve", c, "--vtu", c] + pv, expect="error", inputs=[case_path])
        self.run("sweep csv onto its case", ["sweep", c, "--vary", "operating.speed_rpm=1000:2000:2", "--csv", c] + pv,
                 expect="error", inputs=[case_path])
        self.run("sweep csv and jsonl same", ["sweep", c, "--vary", "operating.speed_rpm=1000:2000:2", "--csv", "x",
                                             "--jsonl", "x"] + pv, expect="error")
        self.run("sweep csv and jsonl both stdout", ["sweep", c, "--vary", "operating.speed_rpm=1000:2000:2", "--csv",
                                                    "-", "--jsonl", "-"] + pv, expect="error")
        self.run("batch csv onto designs", ["batch", "{C}/designs-compressor.csv", "--case", c, "--csv",
                                            "{C}/designs-compressor.csv"] + pv, expect="error",
                 inputs=[str(self.cases / "designs-compressor.csv")])
        self.run("coefficients csv onto case", ["coefficients", c, "--csv", c] + pv, expect="error",
                 inputs=[case_path])
        self.run("rotor json onto rotor", ["rotor", "{C}/rotors/compressor-rotor.toml", "--speeds", "7000:8000:2",
                                           "--json", "{C}/rotors/compressor-rotor.toml"], expect="error",
                 inputs=[str(self.cases / "rotors/compressor-rotor.toml")])
        self.run("solve json into missing dir", ["solve", c, "--json", "/nonexistent/dir/r.json"] + pv, expect="error")
        self.run("solve json onto a directory", ["solve", c, "--json", "{W}"] + pv, expect="error")
        self.run("frf json and csv same", ["frf", "{C}/test-rig.toml", "--json", "x", "--csv", "x"] + pv,
                 expect="error")
        self.run("modes json and csv same", ["modes", c, "--json", "x", "--csv", "x"], expect="error")

    def sweeps(self):
        c = "{C}/compressor-bearing.toml"
        pv = ["--set", 'mesh.fidelity="preview"']
        bad = {
            "same key twice": ["--vary", "operating.load_n=1000,2000", "--vary", "operating.load_n=3000,4000"],
            "misspelt key": ["--vary", "operating.speeed_rpm=1000:2000:2"],
            "steps 0": ["--vary", "operating.speed_rpm=1000:2000:0"],
            "nan bound": ["--vary", "operating.speed_rpm=nan:2000:3"],
            "inf bound": ["--vary", "operating.speed_rpm=1000:inf:3"],
            "million points": ["--vary", "operating.speed_rpm=1000:11000:1000000"],
            "1e12 points": ["--vary", "operating.speed_rpm=1000:11000:1000", "--vary", "operating.load_n=1:2:1000",
                            "--vary", "operating.load_angle_deg=0:10:1000000"],
            "empty list": ["--vary", "operating.speed_rpm="],
            "no equals": ["--vary", "operating.speed_rpm"],
            "param from negative": ["--param", "operating.speed_rpm", "--from", "-5", "--to", "10"],
            "param steps 0": ["--param", "operating.speed_rpm", "--from", "1000", "--to", "2000", "--steps", "0"],
            "out of range values": ["--vary", "operating.speed_rpm=-1000,-2000"],
            "string key numbers": ["--vary", "mesh.fidelity=1,2"],
            "vtu symlink": [],
        }
        for name, a in bad.items():
            expect = "error"
            if name == "out of range values":
                expect = "error"
            if name == "vtu symlink":
                real = self.work / "realdir"
                real.mkdir(exist_ok=True)
                (self.work / "linkdir").mkdir(exist_ok=True)
                target = real / "s.pvd"
                target.write_text("")
                link = self.work / "linkdir" / "s.pvd"
                if not link.exists():
                    os.symlink(target, link)
                self.run("sweep vtu symlink", ["sweep", c, "--vary", "operating.speed_rpm=1000:2000:2", "--vtu",
                                               str(link)] + pv, expect="any")
                continue
            self.run(f"sweep {name}", ["sweep", c] + a + pv, expect=expect)
        self.run("sweep valid", ["sweep", c, "--vary", "operating.speed_rpm=5000:9000:3"] + pv, expect="ok")

    def batches(self):
        c = "{C}/compressor-bearing.toml"
        w = self.work
        tables = {
            "misspelt header": "operating.speeed_rpm\n1000\n2000\n",
            "empty": "",
            "header only": "operating.speed_rpm\n",
            "ragged": "operating.speed_rpm,operating.load_n\n1000\n2000,3,4\n",
            "duplicate header": "operating.speed_rpm,operating.speed_rpm\n1000,2000\n",
            "nan values": "operating.speed_rpm\nnan\ninf\n",
            "binary": None,
        }
        for name, text in tables.items():
            path = w / f"designs-{name.replace(' ', '-')}.csv"
            if text is None:
                path.write_bytes(os.urandom(2000))
            else:
                path.write_text(text)
            expect = "error"
            self.run(f"batch {name}", ["batch", str(path), "--case", c, "--set", 'mesh.fidelity="preview"'],
                     expect=expect)
        for shard in ["0/4", "5/4", "1/0", "a/b", "1/1000000"]:
            self.run(f"batch shard {shard}", ["batch", "{C}/designs-compressor.csv", "--case", c, "--shard", shard,
                                              "--set", 'mesh.fidelity="preview"'],
                     expect="error" if shard != "1/1000000" else "any")

    def coefficient_runs(self):
        c = "{C}/compressor-bearing.toml"
        pv = ["--set", 'mesh.fidelity="preview"']
        for name, a in {
            "ratio negative": ["--excitation-ratio=-1:2:3"],
            "ratio nan": ["--excitation-ratio=nan"],
            "speed million": ["--speed-rpm", "6000:11000:1000000"],
            "speed negative": ["--speed-rpm=-100:100:3"],
            "speed zero steps": ["--speed-rpm", "1000:2000:0"],
            "speed garbage": ["--speed-rpm", "fast"],
            "speed inf": ["--speed-rpm", "1000,inf"],
        }.items():
            self.run(f"coefficients {name}", ["coefficients", c] + a + pv, expect="error")
        self.run("coefficients valid", ["coefficients", c, "--speed-rpm", "6000:9000:3"] + pv, expect="ok")

    def mode_runs(self):
        c = "{C}/compressor-bearing.toml"
        for n in ["0", "7", "1000000", "-1"]:
            self.run(f"modes count {n}", ["modes", c, f"--count={n}"], expect="error")
        self.run("modes fixed sector case", ["modes", "{C}/plain-2groove-ld05.toml"], expect="any")
        self.run("modes valid", ["modes", c, "--count", "2", "--set", 'mesh.fidelity="preview"'], expect="ok")

    def frf_runs(self):
        r = "{C}/test-rig-pub5.toml"
        pv = ["--set", 'mesh.fidelity="preview"']
        for name, a in {
            "amplitude nan": ["--amplitude-v", "nan"],
            "amplitude negative": ["--amplitude-v=-1"],
            "from negative": ["--from=-5"],
            "to below from": ["--from", "100", "--to", "10"],
            "points 0": ["--points", "0"],
            "points huge": ["--points", "100000000"],
            "to inf": ["--to", "inf"],
            "orifices removed": ["--set", "bearing.pads.orifice="],
            "supply below injection": ["--set", "hydraulics.supply_pressure_bar=5"],
        }.items():
            self.run(f"frf {name}", ["frf", r] + a + pv, expect="error")
        self.run("frf no hydraulics", ["frf", "{C}/compressor-bearing.toml"] + pv, expect="error")
        self.run("frf valid", ["frf", r, "--points", "20"] + pv, expect="ok")

    def rotor_runs(self):
        base = (self.cases / "rotors/compressor-rotor.toml").read_text()
        rotor = "{C}/rotors/compressor-rotor.toml"
        for name, a in {
            "speeds huge top": ["--speeds", "1000:1e9:3"],
            "speeds max count": ["--speeds", "1000:13000:10001"],
            "speeds reversed": ["--speeds", "2000:1000:3"],
            "speeds nan": ["--speeds", "nan:1000:3"],
            "speeds one": ["--speeds", "1000:2000:1"],
            "speeds zero": ["--speeds", "0:0:2"],
            "shaft modes 10000": ["--speeds", "7000:8000:2", "--shaft-modes", "10000"],
            "garbage speeds": ["--speeds", "x"],
        }.items():
            expect = "error"
            self.run(f"rotor {name}", ["rotor", rotor] + a, expect=expect)
        self.run("rotor at 0 rpm", ["rotor", rotor, "--speeds", "0:100:2"], expect="any")
        big = "[[rotor.section]]\nlength_mm = 100.0\nouter_diameter_mm = 100.0\nelements = 200\n"
        head = base.split("[[rotor.section]]")[0]
        tail = "[[rotor.bearing]]\nnode = 0\ncase = \"../compressor-bearing.toml\"\n\n" \
               "[[rotor.bearing]]\nnode = 5000\ncase = \"../compressor-bearing.toml\"\n"
        head = re.sub(r"shaft_modes = \d+", "shaft_modes = 0", head)
        (self.cases / "rotors/huge.toml").write_text(head + big * 25 + tail)
        self.run("rotor 25x200 elements", ["rotor", "{C}/rotors/huge.toml", "--speeds", "7000:8000:2"],
                 expect="error")
        mid = "[[rotor.section]]\nlength_mm = 100.0\nouter_diameter_mm = 100.0\nelements = 100\n"
        tail2 = tail.replace("5000", "1500")
        (self.cases / "rotors/big.toml").write_text(head + mid * 15 + tail2)
        self.run("rotor 1500 elements full", ["rotor", "{C}/rotors/big.toml", "--speeds", "7000:8000:2"],
                 expect="error")
        self.run("rotor critical map huge top", ["rotor", rotor, "--critical-map", "--speeds", "1000:1e9:3"],
                 expect="error")

    def control_runs(self):
        active = "{C}/rotors/compressor-rotor-active.toml"
        base = (self.cases / "rotors/compressor-rotor-active.toml").read_text()
        for name, a in {
            "speeds huge top": ["--speeds", "1000:1e9:3"],
            "speeds max count": ["--speeds", "1000:13000:10001"],
            "speeds reversed": ["--speeds", "2000:1000:3"],
            "speeds nan": ["--speeds", "nan:1000:3"],
            "gain nan": ["--speeds", "7000:8000:2", "--gain", "nan"],
            "gain inf": ["--speeds", "7000:8000:2", "--gain=inf"],
            "gain sweep one step": ["--speeds", "7000:8000:2", "--gain-sweep", "0:1:1"],
            "gain sweep 1e6 steps": ["--speeds", "7000:8000:2", "--gain-sweep", "0:1:1000000"],
            "gain sweep garbage": ["--speeds", "7000:8000:2", "--gain-sweep", "a,b"],
            "gain sweep nan": ["--speeds", "7000:8000:2", "--gain-sweep", "1,nan"],
            "max hours 0": ["--speeds", "7000:8000:2", "--max-hours", "0"],
            "max hours nan": ["--speeds", "7000:8000:2", "--max-hours", "nan"],
            "tiny work bound": ["--speeds", "1000:13000:50", "--max-hours", "0.00001"],
        }.items():
            self.run(f"control {name}", ["control", active] + a, expect="error")
        self.run("control without [control]", ["control", "{C}/rotors/compressor-rotor.toml", "--speeds",
                                               "7000:8000:2"], expect="error")
        self.run("control json onto rotor", ["control", active, "--speeds", "7000:8000:2", "--json", active],
                 expect="error", inputs=[str(self.cases / "rotors/compressor-rotor-active.toml")])
        self.run("control valid", ["control", active, "--speeds", "6000:9000:3", "--csv", "c.csv"], expect="ok")
        for key, vals in {"gain": ["nan", "1e300", '"x"'], "sensor_node": ["-1", "100000"],
                          "actuator_bearing": ["7", "-1"]}.items():
            for v in vals:
                text = re.sub(rf"(?m)^{key}\s*=.*$", f"{key} = {v}", base) if re.search(rf"(?m)^{key}\s*=", base) \
                    else base.replace("[control]", f"[control]\n{key} = {v}", 1)
                path = self.cases / "rotors" / f"active-{key}-{abs(hash(v))}.toml"
                path.write_text(text)
                self.run(f"control file {key}={v}", ["control", str(path), "--speeds", "7000:8000:2"], expect="any")

    def ross_runs(self):
        c = "{C}/compressor-bearing.toml"
        pv = ["--set", 'mesh.fidelity="preview"']
        for name, a in {
            "ross nodes and tags mismatch": ["--node", "3,12,20", "--tag", "a,b"],
            "ross node negative": ["--node=-1"],
            "ross node garbage": ["--node", "x"],
            "ross analysis reversed": ["--speed-rpm", "6000:9000:3", "--analysis-rpm", "9000:6000"],
            "ross analysis nan": ["--speed-rpm", "6000:9000:3", "--analysis-rpm", "nan:6000"],
            "ross onto case": ["--speed-rpm", "6000:9000:3", "--ross", c],
            "ross and csv same": ["--speed-rpm", "6000:9000:3", "--csv", "x", "--ross", "x"],
            "ross tiny work bound": ["--speed-rpm", "6000:9000:30", "--max-hours", "0.000001"],
        }.items():
            self.run(f"coefficients {name}", ["coefficients", c] + a + (["--ross", "r.toml"] if "--ross" not in a
                                                                      else []) + pv,
                     expect="error", inputs=[str(self.cases / "compressor-bearing.toml")])
        self.run("coefficients ross two nodes", ["coefficients", c, "--speed-rpm", "6000:9000:3", "--node", "3,12",
                                                 "--ross", "r.toml"] + pv, expect="ok")

    def physics_options(self):
        """The film options added since the harness was first written, alone and together, at their extremes."""
        c = "{C}/compressor-bearing.toml"
        pv = ["--set", 'mesh.fidelity="preview"']
        jfo = ["--set", 'physics.cavitation="jfo"']
        turb = ["--set", 'physics.turbulence="on"']
        combos = {
            "jfo": jfo,
            "jfo thd": jfo + ["--set", 'thermal.model="thd"'],
            "jfo starved": jfo + ["--set", "operating.supply_flow_l_per_min=1"],
            "jfo starved tiny": jfo + ["--set", "operating.supply_flow_l_per_min=1e-6"],
            "reynolds starved": ["--set", "operating.supply_flow_l_per_min=1"],
            "turbulent": turb,
            "turbulent jfo": turb + jfo,
            "turbulent thd": turb + ["--set", 'thermal.model="thd"'],
            "transition reversed": ["--set", 'physics.turbulence="auto"', "--set",
                                    "physics.transition_reynolds_start=2000", "--set",
                                    "physics.transition_reynolds_end=1000"],
            "transition nan": ["--set", 'physics.turbulence="auto"', "--set", "physics.transition_reynolds_start=nan"],
            "gumbel speed 0": ["--set", 'physics.cavitation="gumbel"', "--set", "operating.speed_rpm=0"],
            "jfo speed 0": jfo + ["--set", "operating.speed_rpm=0"],
            "budget 100 film solves": ["--set", "physics.max_film_solves_per_pad=100"],
            "prescribed eccentricity 0.99": ["--set", "operating.eccentricity_ratio=0.99"],
            "prescribed eccentricity 1.5": ["--set", "operating.eccentricity_ratio=1.5"],
        }
        for name, a in combos.items():
            self.run(f"solve {name}", ["solve", c] + a + pv + ["--json", "r.json"], expect="any")
            self.run(f"sweep {name}", ["sweep", c, "--vary", "operating.load_n=1000:20000:3"] + a + pv, expect="any")
        active = "{C}/compressor-bearing-active.toml"
        self.run("frf jfo", ["frf", active, "--points", "20"] + jfo + pv, expect="any")
        self.run("frf turbulent", ["frf", active, "--points", "20"] + turb + pv, expect="any")
        self.run("coefficients jfo turbulent ross", ["coefficients", c, "--speed-rpm", "6000:9000:3", "--node", "3,12",
                                                     "--ross", "r.toml"] + jfo + turb + pv, expect="any")

    def new_inputs(self):
        """Inputs added in the third round: feeding keys and per-pad supply lists, the turbulence band, controller
        files, huge meshes, symlinks, read-only outputs, the Sommerfeld chart and the convergence map's points."""
        c = "{C}/compressor-bearing.toml"
        case_path = str(self.cases / "compressor-bearing.toml")
        pv = ["--set", 'mesh.fidelity="preview"']
        jfo = ["--set", 'physics.cavitation="jfo"']
        thd = ["--set", 'thermal.model="thd"']
        for name, a in {
            "pad supply list short": jfo + ["--set", "operating.pad_supply_flow_l_per_min=[1,2]"],
            "pad supply list long": jfo + ["--set", "operating.pad_supply_flow_l_per_min=[1,2,3,4,5,6,7]"],
            "pad supply list nan": jfo + ["--set", "operating.pad_supply_flow_l_per_min=[1,nan,1,1,1]"],
            "pad supply list negative": jfo + ["--set", "operating.pad_supply_flow_l_per_min=[-1,1,1,1,1]"],
            "pad supply list zero": jfo + ["--set", "operating.pad_supply_flow_l_per_min=[0,0,0,0,0]"],
            "pad supply list strings": jfo + ["--set", 'operating.pad_supply_flow_l_per_min=["a"]'],
            "pad supply list empty": jfo + ["--set", "operating.pad_supply_flow_l_per_min=[]"],
            "pad supply list tiny": jfo + ["--set", "operating.pad_supply_flow_l_per_min=[1e-9,1e-9,1e-9,1e-9,1e-9]"],
            "pad supply without jfo": ["--set", "operating.pad_supply_flow_l_per_min=[1,1,1,1,1]"],
            "pad supply and supply flow": jfo + ["--set", "operating.pad_supply_flow_l_per_min=[1,1,1,1,1]", "--set",
                                                 "operating.supply_flow_l_per_min=5"],
            "feeding groove carry 1": thd + ["--set", 'feeding.kind="leading_edge_groove"', "--set",
                                             "feeding.groove_carry_over=1"],
            "feeding groove carry 2": thd + ["--set", 'feeding.kind="leading_edge_groove"', "--set",
                                             "feeding.groove_carry_over=2"],
            "feeding groove carry nan": thd + ["--set", 'feeding.kind="leading_edge_groove"', "--set",
                                               "feeding.groove_carry_over=nan"],
            "feeding kind unknown": thd + ["--set", 'feeding.kind="bath"'],
            "feeding spray bar starved": thd + jfo + ["--set", 'feeding.kind="spray_bar"', "--set",
                                                      "operating.supply_flow_l_per_min=0.5"],
            "turbulence band empty": ["--set", 'physics.turbulence="auto"', "--set",
                                      "physics.transition_reynolds_start=1500", "--set",
                                      "physics.transition_reynolds_end=1500"],
            "turbulence band huge": ["--set", 'physics.turbulence="auto"', "--set",
                                     "physics.transition_reynolds_end=1e9"],
            "turbulence at 1e6 rpm": ["--set", 'physics.turbulence="on"', "--set", "operating.speed_rpm=1e6"],
            "turbulence thd jfo starved": ["--set", 'physics.turbulence="auto"'] + thd + jfo + [
                "--set", "operating.supply_flow_l_per_min=1"],
        }.items():
            self.run(f"new solve {name}", ["solve", c] + a + pv + ["--json", "r.json"], expect="any")
        # the full-model mesh under the node cap, and meshes beyond the caps
        for name, a in {
            "full model 440x216": ["--set", "mesh.half_model=false", "--set", "mesh.circumferential_elements=440",
                                   "--set", "mesh.axial_elements=216"],
            "mesh 1e6 elements": ["--set", "mesh.circumferential_elements=1000000"],
            "mesh nodes cap raised": ["--set", "mesh.circumferential_elements=3000", "--set",
                                      "mesh.axial_elements=3000", "--set", "mesh.max_nodes=100000000"],
            "mesh thd pad solids huge": thd + ["--set", "mesh.pad_radial_elements=1000"],
        }.items():
            self.run(f"new mesh {name}", ["solve", c] + a + ["--json", "r.json"], expect="any")
        # controller files for the rig's closed loop (frf --control)
        rig = "{C}/test-rig-pub5.toml"
        ctl = (self.cases / "controllers/test-rig-pub5-control.toml").read_text()
        bad_ctl = {
            "empty": "",
            "no control table": "title = 'x'\n",
            "gain nan": ctl.replace("gain = 1.0", "gain = nan"),
            "sensor bearing 7": ctl.replace("bearing = 0\ndirection", "bearing = 7\ndirection"),
            "actuator missing": re.sub(r"(?s)\[\[control.actuator\]\].*?(?=\[\[control.loop)", "", ctl),
            "loop sensor 9": ctl.replace("sensor = 0", "sensor = 9"),
            "law unknown": ctl.replace('law = "pd"', 'law = "fuzzy"'),
            "kp inf": re.sub(r"kp_v_per_um = .*", "kp_v_per_um = inf", ctl),
            "kp 1e300": re.sub(r"kp_v_per_um = .*", "kp_v_per_um = 1e300", ctl),
            "garbage": None,
        }
        for name, text in bad_ctl.items():
            path = self.work / f"ctl-{name.replace(' ', '-')}.toml"
            if text is None:
                path.write_bytes(os.urandom(3000))
            else:
                path.write_text(text)
            expect = "any" if name in ("kp 1e300",) else "error"
            self.run(f"new frf control {name}", ["frf", rig, "--control", str(path), "--points", "10"] + pv,
                     expect=expect)
        self.run("new frf control is the case", ["frf", rig, "--control", rig, "--points", "10"] + pv, expect="error")
        self.run("new frf control missing", ["frf", rig, "--control", "{W}/nope.toml", "--points", "10"] + pv,
                 expect="error")
        # symlinks
        w = self.work
        loop_a, loop_b = w / "loop-a.toml", w / "loop-b.toml"
        if not loop_a.is_symlink():
            os.symlink(loop_b, loop_a)
            os.symlink(loop_a, loop_b)
        self.run("new symlink loop case", ["solve", str(loop_a)], expect="error")
        dangling = w / "dangling.toml"
        if not dangling.is_symlink():
            os.symlink(w / "gone.toml", dangling)
        self.run("new symlink dangling case", ["solve", str(dangling)], expect="error")
        link_to_case = w / "link-to-case.json"
        if not link_to_case.is_symlink():
            os.symlink(self.cases / "compressor-bearing.toml", link_to_case)
        self.run("new json through a symlink onto the case", ["solve", c, "--json", str(link_to_case)] + pv,
                 expect="error", inputs=[case_path])
        self.run("new csv through a symlink onto the case", ["sweep", c, "--vary", "operating.speed_rpm=1000:2000:2",
                                                             "--csv", str(link_to_case)] + pv,
                 expect="error", inputs=[case_path])
        hard = w / "hard-case.json"
        if not hard.exists():
            os.link(self.cases / "compressor-bearing.toml", hard)
        self.run("new json onto a hard link of the case", ["solve", c, "--json", str(hard)] + pv, expect="error",
                 inputs=[case_path])
        # read-only outputs (meaningless as root, who may write anywhere)
        ro = w / "readonly"
        ro.mkdir(exist_ok=True)
        (ro / "r.json").write_text("keep me\n")
        os.chmod(ro / "r.json", 0o444)
        os.chmod(ro, 0o555)
        if os.geteuid() != 0:
            self.run("new json into a read-only dir", ["solve", c, "--json", str(ro / "new.json")] + pv,
                     expect="error")
            self.run("new json onto a read-only file", ["solve", c, "--json", str(ro / "r.json")] + pv,
                     expect="error", inputs=[str(ro / "r.json")])
            self.run("new sweep csv into a read-only dir", ["sweep", c, "--vary", "operating.speed_rpm=1000:2000:2",
                                                           "--csv", str(ro / "p.csv")] + pv, expect="error")
            self.run("new rotor csv into a read-only dir", ["rotor", "{C}/rotors/compressor-rotor.toml", "--speeds",
                                                           "7000:8000:2", "--csv", str(ro / "r.csv")],
                     expect="error")
        self.run("new json to /dev/full", ["solve", c, "--json", "/dev/full"] + pv, expect="error")
        # the Sommerfeld chart
        for name, a in {
            "points 0": ["--points", "0"],
            "points 1": ["--points", "1"],
            "points 102": ["--points", "102"],
            "points huge": ["--points", "1000000000000"],
            "points garbage": ["--points", "x"],
            "csv onto case": ["--csv", c],
            "csv and json same": ["--csv", "x", "--json", "x"],
        }.items():
            self.run(f"new sommerfeld {name}", ["sommerfeld", c] + a + pv, expect="error",
                     inputs=[case_path] if "onto" in name else ())
        self.run("new sommerfeld zero load", ["sommerfeld", c, "--set", "operating.load_n=0"] + pv, expect="any")
        self.run("new sommerfeld jfo starved", ["sommerfeld", c, "--points", "4"] + jfo + [
            "--set", "operating.supply_flow_l_per_min=1"] + pv, expect="any")
        self.run("new sommerfeld valid", ["sommerfeld", "{C}/plain-360-sommerfeld.toml", "--points", "4"] + pv,
                 expect="ok")
        # the convergence map's selections
        for name, a in {
            "points off grid": ["--only-points", "67@0.1"],
            "points bad S": ["--only-points", "65@0.2"],
            "points garbage": ["--only-points", "x"],
            "points nan": ["--only-points", "nan@0.1"],
            "points with update-doc": ["--only-points", "65@0.1", "--update-doc"],
            "only nothing": ["--only", "no-such-bearing"],
            "step 0": ["--step-deg", "0"],
            "step nan": ["--step-deg", "nan"],
        }.items():
            self.run(f"new convergence-map {name}", ["convergence-map", "--root", str(ROOT)] + a, expect="error")
        self.run("new convergence-map one point", ["convergence-map", "--root", str(ROOT), "--only", "someya",
                                                   "--only-points", "90@1", "--csv", "m.csv"], expect="ok")
        # the schema's outputs
        self.run("new schema json onto a directory", ["schema", "--json", "{W}"], expect="error")
        self.run("new schema rotor", ["schema", "--rotor"], expect="ok")
        # batches with the keys added since
        for name, text in {
            "pad supply column": "operating.pad_supply_flow_l_per_min\n1\n",
            "feeding kind column": "feeding.kind\nbath\n",
            "turbulence column": "physics.turbulence\nsometimes\n",
        }.items():
            path = w / f"designs-new-{name.replace(' ', '-')}.csv"
            path.write_text(text)
            self.run(f"new batch {name}", ["batch", str(path), "--case", c] + pv, expect="error")
        # rotors: a bearing case that is bad, and a rotor whose bearing case is the rotor itself
        base = (self.cases / "rotors/compressor-rotor.toml").read_text()
        (self.cases / "rotors/self.toml").write_text(base.replace("../compressor-bearing.toml", "self.toml"))
        self.run("new rotor bearing case is the rotor", ["rotor", "{C}/rotors/self.toml", "--speeds", "7000:8000:2"],
                 expect="error")
        (self.cases / "rotors/nan-case.toml").write_text(base.replace("../compressor-bearing.toml", "../nan.toml"))
        (self.cases / "nan.toml").write_text((self.cases / "compressor-bearing.toml").read_text()
                                             .replace("load_n = ", "load_n = nan # ", 1))
        self.run("new rotor bearing case with nan load", ["rotor", "{C}/rotors/nan-case.toml", "--speeds",
                                                          "7000:8000:2"], expect="error")

    def round4_inputs(self):
        """Inputs added in the fourth round: large full shafts (the eigen-solutions in the estimate), the mesh
        just under the node cap that plans more than 8 GB, the modes command's estimate, the map's row update."""
        c = "{C}/compressor-bearing.toml"
        base = (self.cases / "rotors/compressor-rotor.toml").read_text()
        head = re.sub(r"shaft_modes = \d+", "shaft_modes = 0", base.split("[[rotor.section]]")[0])
        for elements in [300, 400]:
            sections = "[[rotor.section]]\nlength_mm = 300.0\nouter_diameter_mm = 101.6\nelements = %d\n\n" % (
                elements // 4)
            tail = "[[rotor.bearing]]\nnode = %d\ncase = \"../compressor-bearing.toml\"\n\n" \
                   "[[rotor.bearing]]\nnode = %d\ncase = \"../compressor-bearing.toml\"\n" % (
                       elements // 20, elements - elements // 20)
            (self.cases / f"rotors/full-{elements}.toml").write_text(head + sections * 4 + tail)
        full = "{C}/rotors/full-400.toml"
        for name, a, expect in [
            ("1000 speeds", ["--speeds", "1000:13000:1000"], "error"),
            ("10000 speeds", ["--speeds", "1000:13000:10000", "--max-points", "10000"], "error"),
            ("3 speeds", ["--speeds", "3000:4000:3"], "ok"),
            ("reduced 1000 speeds", ["--speeds", "1000:13000:1000", "--shaft-modes", "8", "--max-hours", "0.001"],
             "error"),
            ("critical map", ["--speeds", "1000:13000:20", "--critical-map"], "any"),
        ]:
            self.run(f"round4 rotor full 400 {name}", ["rotor", full] + a, expect=expect)
        self.run("round4 rotor full 300 onto itself", ["rotor", "{C}/rotors/full-300.toml", "--speeds", "3000:4000:2",
                                                     "--json", "{C}/rotors/full-300.toml"], expect="error",
                 inputs=[str(self.cases / "rotors/full-300.toml")])
        self.run("round4 control full shaft", ["control", "{C}/rotors/compressor-rotor-active.toml", "--speeds",
                                                "1000:13000:2000", "--max-points", "2000"], expect="any")
        for name, a, expect in [
            ("mesh 3.98M nodes", ["--set", "mesh.half_model=false", "--set", "mesh.circumferential_elements=1260",
                                  "--set", "mesh.axial_elements=630", "--set", "mesh.max_nodes=4000000"], "error"),
            ("mesh 50M cap", ["--set", "mesh.circumferential_elements=2000", "--set", "mesh.axial_elements=1000",
                              "--set", "mesh.max_nodes=50000000"], "error"),
        ]:
            self.run(f"round4 solve {name}", ["solve", c] + a + ["--json", "r.json"], expect=expect)
        flex = "{C}/compressor-bearing-flexible.toml"
        self.run("round4 modes table", ["modes", flex, "--table", "--csv", "t.csv"], expect="ok")
        self.run("round4 modes 6 on a fine mesh", ["modes", flex, "--count", "6", "--set",
                                                     'mesh.fidelity="reference"'], expect="ok")
        self.run("round4 flexible 3 modes thd", ["solve", flex, "--set", "physics.pad_modes=3", "--set",
                                                  'thermal.model="thd"', "--json", "r.json"], expect="any")
        for name, a in {
            "update-doc family": ["--only", "3 pads,", "--update-doc"],
            "update-doc points": ["--only", "someya", "--only-points", "90@1", "--update-doc"],
            "update-doc quick": ["--only", "someya", "--quick", "--update-doc"],
        }.items():
            self.run(f"round4 convergence-map {name}", ["convergence-map", "--root", str(ROOT)] + a, expect="error")

    def round5_inputs(self):
        """Inputs added in the fifth round: the mesh that plans more than 8 GB on every bearing command (only
        `solve` refused it up front; `coefficients` without `--speed-rpm` built it towards 8 GB)."""
        c = "{C}/compressor-bearing.toml"
        mesh = ["--set", "mesh.half_model=false", "--set", "mesh.circumferential_elements=1260", "--set",
                "mesh.axial_elements=630", "--set", "mesh.max_nodes=4000000"]
        for name, a in [
            ("coefficients", ["coefficients", c]),
            ("coefficients excitation", ["coefficients", c, "--excitation-ratio", "0.5,1,2"]),
            ("coefficients speeds", ["coefficients", c, "--speed-rpm", "6000:7000:2"]),
            ("sommerfeld", ["sommerfeld", c, "--points", "2"]),
            ("sweep", ["sweep", c, "--vary", "operating.speed_rpm=6000:7000:2"]),
            ("frf", ["frf", c]),
            ("modes", ["modes", c, "--set", "physics.pad_modes=1"]),
        ]:
            self.run(f"round5 mesh 3.98M {name}", a + mesh, expect="error")

    def round6_inputs(self):
        """Inputs added in the sixth round, for what the last two sessions added or changed: the starved supply
        flow, the feeding keys, the turbulence band, the Sommerfeld chart, `control`'s flags, batch headers,
        `--vary` over the alternative geometry keys (preload, pad clearance, bore radius) and the JSON the Python
        package reads (solutions and error rows)."""
        c = "{C}/compressor-bearing.toml"
        starved = "{C}/compressor-bearing-starved.toml"
        case_path = str(self.cases / "compressor-bearing.toml")
        pv = ["--set", 'mesh.fidelity="preview"']
        thd = ["--set", 'thermal.model="thd"']
        groove = thd + ["--set", 'feeding.kind="leading_edge_groove"']
        runs = {
            # starvation: the supply flow at and beyond its ends, swept, and on the chart
            "starved supply 1e-12": (["solve", starved, "--set", "operating.supply_flow_l_per_min=1e-12", "--json",
                                      "r.json"], "any"),
            "starved supply nan": (["solve", starved, "--set", "operating.supply_flow_l_per_min=nan"], "error"),
            "starved supply -5": (["solve", starved, "--set", "operating.supply_flow_l_per_min=-5"], "error"),
            "starved sweep through zero": (["sweep", starved, "--vary", "operating.supply_flow_l_per_min=0,5,1e6",
                                            "--jsonl", "r.jsonl"], "any"),
            "starved thd groove": (["solve", starved, "--json", "r.json"] + groove, "any"),
            "starved pad list over supply": (["solve", starved, "--set",
                                              "operating.pad_supply_flow_l_per_min=[1,1,1,1,1]"], "any"),
            # feeding keys
            "groove wider than the gap": (["solve", c, "--set", "feeding.groove_width_deg=80"] + groove, "error"),
            "groove width 0": (["solve", c, "--set", "feeding.groove_width_deg=0"] + groove, "error"),
            # the later --set wins: a feeding kind given after the churning factor replaces it (with a note),
            # a churning factor given after a groove is refused
            "churning then a groove": (["solve", c, "--set", "feeding.churning_factor=5"] + groove, "ok"),
            "a groove then churning": (["solve", c] + groove + ["--set", "feeding.churning_factor=5"], "error"),
            "churning nan": (["solve", c, "--set", "feeding.churning_factor=nan"], "error"),
            "ram coefficient 2": (["solve", c, "--set", "feeding.ram_pressure_coefficient=2"], "error"),
            "vary feeding kinds": (["sweep", c, "--vary", "feeding.kind=flooded,leading_edge_groove,spray_bar,bath"]
                                   + thd + ["--jsonl", "r.jsonl"], "any"),
            "vary groove carry over out of range": (["sweep", c, "--vary", "feeding.groove_carry_over=-1:2:4"] + groove,
                                                    "any"),
            # the turbulence band
            "transition start 0": (["solve", c, "--set", 'physics.turbulence="auto"', "--set",
                                    "physics.transition_reynolds_start=0"], "error"),
            "transition end below start": (["sweep", c, "--set", 'physics.turbulence="auto"', "--vary",
                                            "physics.transition_reynolds_end=10,100000"], "any"),
            "vary turbulence words": (["sweep", c, "--vary", "physics.turbulence=off,auto,on,sometimes"], "any"),
            # the Sommerfeld chart
            "sommerfeld starved": (["sommerfeld", starved, "--points", "3", "--json", "s.json"], "any"),
            "sommerfeld position load": (["sommerfeld", c, "--points", "3", "--set",
                                          "operating.eccentricity_ratio=0.5"], "any"),
            "sommerfeld zero speed": (["sommerfeld", c, "--points", "3", "--set", "operating.speed_rpm=0"], "error"),
            "sommerfeld json to /dev/full": (["sommerfeld", c, "--points", "3", "--json", "/dev/full"], "error"),
            "sommerfeld json onto case": (["sommerfeld", c, "--points", "3", "--json", c], "error"),
            "sommerfeld thd two points": (["sommerfeld", c, "--points", "2", "--csv", "s.csv"] + thd, "any"),
            # control's flags
            "control root locus nan": (["control", "{C}/rotors/compressor-rotor-active.toml", "--speeds",
                                        "7000:8000:2", "--root-locus", "nan"], "error"),
            "control root locus negative": (["control", "{C}/rotors/compressor-rotor-active.toml", "--speeds",
                                             "7000:8000:2", "--root-locus=-100"], "error"),
            "control root locus 1e12": (["control", "{C}/rotors/compressor-rotor-active.toml", "--speeds",
                                         "7000:8000:2", "--root-locus", "1e12"], "any"),
            "control gain csv without sweep": (["control", "{C}/rotors/compressor-rotor-active.toml", "--speeds",
                                                "7000:8000:2", "--gain-csv", "g.csv"], "error"),
            "control locus csv without locus": (["control", "{C}/rotors/compressor-rotor-active.toml", "--speeds",
                                                 "7000:8000:2", "--locus-csv", "l.csv"], "error"),
            "control gain 1e300": (["control", "{C}/rotors/compressor-rotor-active.toml", "--speeds", "7000:8000:2",
                                    "--gain", "1e300", "--json", "c.json"], "any"),
            "control gain csv onto rotor": (["control", "{C}/rotors/compressor-rotor-active.toml", "--speeds",
                                             "7000:8000:2", "--gain-sweep", "0:1:2", "--gain-csv",
                                             "{C}/rotors/compressor-rotor-active.toml"], "error"),
            # --vary over the alternative geometry keys
            "vary clearance for bore": (["sweep", c, "--vary", "bearing.pads.clearance_um=100:150:3"], "ok"),
            "vary preload out of range": (["sweep", c, "--vary", "bearing.pads.preload=1.5,-3"], "error"),
            "vary clearance non-positive": (["sweep", c, "--vary", "bearing.pads.clearance_um=0,-1"], "error"),
            "vary bore below journal": (["sweep", c, "--vary", "bearing.pads.bore_radius_mm=1,50"], "any"),
            "vary preload and clearance": (["sweep", c, "--vary", "bearing.pads.preload=0.2,0.3", "--vary",
                                            "bearing.pads.clearance_um=120"], "error"),
            "vary one pad's preload": (["sweep", c, "--vary", "bearing.pad[2].preload=0,0.5"], "any"),
            "vary pad 9's preload": (["sweep", c, "--vary", "bearing.pad[9].preload=0,0.5"], "error"),
            # the JSON the Python package reads: solutions at the edges and error rows
            "json of a zero load": (["solve", c, "--set", "operating.load_n=0", "--json", "r.json"], "any"),
            "json of a position": (["solve", c, "--set", "operating.eccentricity_ratio=0.9", "--json", "r.json"],
                                   "any"),
            "jsonl of failing points": (["sweep", c, "--vary", "operating.load_n=1e9,1e12", "--jsonl", "r.jsonl"],
                                        "error"),
        }
        for name, (a, expect) in runs.items():
            self.run(f"round6 {name}", a + pv, expect=expect, inputs=[case_path, str(self.cases /
                                                                                   "rotors/compressor-rotor-active.toml")])
        # batch headers
        w = self.work
        for name, text, expect in [
            ("header with spaces", " operating.speed_rpm , operating.load_n \n7000,1000\n", "any"),
            ("header with a BOM", "\ufeffoperating.speed_rpm\n7000\n", "any"),
            ("header empty column", "operating.speed_rpm,\n7000,1\n", "error"),
            ("header text key", "title\nabc\n", "any"),
            ("header pad 9", "bearing.pad[9].offset\n0.5\n", "error"),
            ("header preload and clearance", "bearing.pads.preload,bearing.pads.clearance_um\n0.3,120\n", "error"),
            ("header fidelity word", "mesh.fidelity\nultra\n", "error"),
            ("header quoted key", '"operating.speed_rpm"\n7000\n', "any"),
        ]:
            path = w / f"designs-r6-{name.replace(' ', '-')}.csv"
            path.write_text(text, encoding="utf-8")
            self.run(f"round6 batch {name}", ["batch", str(path), "--case", c, "--jsonl", "b.jsonl"] + pv,
                     expect=expect)

    def misc(self):
        self.run("schema", ["schema"], expect="ok")
        self.run("unknown command", ["frobnicate"], expect="error")
        self.run("solve set unknown key", ["solve", "{C}/compressor-bearing.toml", "--set", "no.such=1"],
                 expect="error")
        self.run("solve set malformed", ["solve", "{C}/compressor-bearing.toml", "--set", "novalue"], expect="error")
        self.run("bench bad section", ["bench", "--only", "nothing"], expect="error")
        self.run("convergence map bad step", ["convergence-map", "--step-deg", "7"], expect="error")

    def report(self):
        counts = {}
        for r in self.runs:
            for v in r["verdicts"]:
                counts[v] = counts.get(v, 0) + 1
        self.out.mkdir(parents=True, exist_ok=True)
        with open(self.out / "runs.jsonl", "w") as f:
            for r in self.runs:
                f.write(json.dumps(r) + "\n")
        summary = {"runs": len(self.runs), "counts": counts,
                   "max_seconds": max((r["seconds"] for r in self.runs), default=0)}
        (self.out / "summary.json").write_text(json.dumps(summary, indent=1))
        print(json.dumps(summary, indent=1))
        shutil.rmtree(self.work, ignore_errors=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", default=str(ROOT / "target/release/tiltpad"))
    ap.add_argument("--out", default="target/bad-inputs")
    ap.add_argument("--timeout", type=float, default=60)
    ap.add_argument("--mem-gb", type=float, default=8)
    ap.add_argument("--only", default=None, help="only the runs whose name contains one of these comma-separated words")
    ap.add_argument("--skip-keys", action="store_true", help="skip the per-key --set values")
    ap.add_argument("--keys-only", action="store_true", help="only the per-key --set values (to run beside a "
                    "--skip-keys run)")
    a = ap.parse_args()
    h = Harness(a.bin, a.out, a.timeout, a.mem_gb, a.only)
    try:
        if a.keys_only:
            h.set_keys()
            return
        h.files()
        h.outputs()
        h.sweeps()
        h.batches()
        h.coefficient_runs()
        h.mode_runs()
        h.frf_runs()
        h.rotor_runs()
        h.control_runs()
        h.ross_runs()
        h.physics_options()
        h.new_inputs()
        h.round4_inputs()
        h.round5_inputs()
        h.round6_inputs()
        h.misc()
        h.solve_extremes()
        if not a.skip_keys:
            h.set_keys()
    finally:
        h.report()


if __name__ == "__main__":
    sys.exit(main())
