"""What the LIGGGHTS tests share: running an input through a launcher, reading its log
(thermo tables), the fix's output files (profile, VTK) and dumps, and the checks' helpers."""
import math
import os
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))
INPUTS = os.path.join(HERE, "inputs")
MESHES = os.path.join(HERE, "meshes")
# a run that takes longer has gone wrong (the longest case takes seconds); LIGGGHTS ignores
# SIGTERM (its handler only flags it), so the child is killed with SIGKILL
RUN_TIMEOUT = 600


class CheckFailed(Exception):
    pass


def expect(condition, message):
    if not condition:
        raise CheckFailed(message)


def close(a, b, tol, what):
    expect(abs(a - b) <= tol, f"{what}: {a!r} vs {b!r} (tolerance {tol:g})")


def thermo_tables(log_text):
    """Every run's thermo table as a list of {column: value} rows."""
    tables, header = [], None
    for line in log_text.splitlines():
        words = line.split()
        if words[:1] == ["Step"]:
            header = words
            tables.append([])
        elif header and words[:2] == ["Loop", "time"]:
            header = None
        elif header and len(words) == len(header):
            try:
                tables[-1].append(dict(zip(header, map(float, words))))
            except ValueError:
                pass    # a warning line of the same length
    return tables


def run(command, workdir, what, exit_codes=(0,)):
    """Runs command in workdir; its output (stdout and stderr)."""
    try:
        done = subprocess.run(command, cwd=workdir, stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, universal_newlines=True,
                              errors="replace", timeout=RUN_TIMEOUT)
    except subprocess.TimeoutExpired:
        raise CheckFailed(f"{what} ran longer than {RUN_TIMEOUT} s: {' '.join(command)}")
    if done.returncode not in exit_codes:
        print(done.stdout[-6000:])
        raise CheckFailed(f"{what} exited with {done.returncode}: {' '.join(command)}")
    return done.stdout


def input_command(launcher, input_path, variables, log_name):
    command = launcher + ["-in", input_path, "-log", log_name, "-echo", "none",
                          "-var", "inputs", INPUTS, "-var", "meshes", MESHES]
    for name, value in variables.items():
        command += ["-var", name, str(value)]
    return command


def run_input(launcher, input_name, variables, workdir, log_name=None):
    """Runs inputs/INPUT_NAME; returns (thermo tables, log text)."""
    log_name = log_name or "log." + input_name[3:]
    run(input_command(launcher, os.path.join(INPUTS, input_name), variables, log_name), workdir,
        input_name)
    with open(os.path.join(workdir, log_name)) as f:
        log = f.read()
    tables = thermo_tables(log)
    expect(tables and all(tables), f"{input_name}: no thermo output")
    return tables, log


def run_text(launcher, text, workdir, name, fail=False):
    """Runs the input `text` (written to workdir/in.NAME); its output. With `fail`, the
    input must fail."""
    path = os.path.join(workdir, "in." + name)
    with open(path, "w") as f:
        f.write(text)
    return run(input_command(launcher, path, {}, "log." + name), workdir, name,
               exit_codes=range(1, 256) if fail else (0,))


def error_message(launcher, text, workdir, name):
    """The message of the first ERROR line of the input `text`, which must fail, without
    the (file:line) LIGGGHTS and LAMMPS append."""
    out = run_text(launcher, text, workdir, name, fail=True)
    for line in out.splitlines():
        if line.startswith("ERROR"):
            message = line.split(":", 1)[1].strip()
            return message[:message.rfind(" (")] if message.endswith(")") else message
    raise CheckFailed(f"{name} failed without an ERROR line:\n{out[-3000:]}")


# ---- the fix's outputs --------------------------------------------------------------------

def read_profile(path):
    """The blocks of a darcy/pressure profile file: {step: (time, [[z, p, phi, k, vbar_z]])}."""
    with open(path) as f:
        lines = [line for line in f if not line.startswith("#")]
    blocks, i = {}, 0
    while i < len(lines):
        step, time, layers, _active = lines[i].split()
        rows = [list(map(float, line.split()[1:])) for line in lines[i + 1:i + 1 + int(layers)]]
        blocks[int(step)] = (float(time), rows)
        i += 1 + int(layers)
    return blocks


def read_vtk(path):
    """The cell fields of a darcy/pressure VTK file: {name: [values]} (vectors flattened)."""
    fields, name = {}, None
    with open(path) as f:
        for line in f:
            words = line.split()
            if words[:1] in (["SCALARS"], ["VECTORS"]):
                name = words[1]
                fields[name] = []
            elif name and words and words[0] != "LOOKUP_TABLE":
                fields[name] += [float(w) for w in words]
    return fields


def read_rows(path):
    """A dump written with write_dump (or dump custom) as {atom ID: [columns after the ID]}."""
    rows, section = {}, False
    with open(path) as f:
        for line in f:
            if line.startswith("ITEM:"):
                section = line.startswith("ITEM: ATOMS")
            elif section:
                words = line.split()
                rows[int(words[0])] = [float(w) for w in words[1:]]
    return rows


class Launch:
    """One launcher (with its mpirun prefix) in one work folder."""

    def __init__(self, launcher, workdir, np=1):
        self.launcher, self.workdir, self.np = launcher, workdir, np

    def run(self, input_name, variables=None, log_name=None):
        """(thermo tables, log text) of inputs/INPUT_NAME"""
        return run_input(self.launcher, input_name, variables or {}, self.workdir, log_name)

    def run_text(self, text, name):
        """the output of the input `text`, which must succeed"""
        return run_text(self.launcher, text, self.workdir, name)

    def error(self, text, name):
        """the ERROR message of the input `text`, which must fail"""
        return error_message(self.launcher, text, self.workdir, name)

    def path(self, name):
        return os.path.join(self.workdir, name)
