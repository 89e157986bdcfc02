"""Helpers for case-based tests: copy a tutorial, edit dictionaries, run
OpenFOAM applications, list time directories and read ascii fields.

Standard library and numpy only. All paths may be str or os.PathLike.

    import foamcase as fc
    case = fc.copy_tutorial("waterAirShockTube", "V2_n100")
    fc.set_entry(case, "system/blockMeshDict", "nx", 100)
    fc.run(case, "./Allrun", log="log.Allrun")
    t = fc.latest_time(case)
    rho = fc.read_field(case, t, "rho")          # (N,)
    U = fc.read_field(case, t, "U")              # (N, 3)
    C = fc.cell_centres(case, t)                 # (N, 3)
"""
import gzip
import os
import re
import shutil
import subprocess

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
TESTS_DIR = os.path.dirname(HERE)
PROJECT_DIR = os.path.dirname(TESTS_DIR)
TUTORIALS_DIR = os.path.join(PROJECT_DIR, "tutorials", "impactFoam")
RUN_DIR = os.path.join(TESTS_DIR, "run")


class FoamError(RuntimeError):
    """A command failed or a file could not be read. str(e) may span many
    lines (a log tail); e.summary is one line for a FAIL message."""

    def __init__(self, message, summary=None):
        RuntimeError.__init__(self, message)
        self.summary = summary or message.splitlines()[0]


def log_summary(text):
    """One line saying why a run failed, from a log text: the message after
    'FOAM FATAL ERROR' / 'FOAM FATAL IO ERROR', else the last line that
    mentions an error, else the last non-empty line."""
    lines = [l.strip() for l in text.splitlines()]
    for i in range(len(lines) - 1, -1, -1):
        if "FOAM FATAL" in lines[i]:
            rest = [l for l in lines[i + 1:i + 6] if l]
            if rest:
                return "FOAM FATAL: " + rest[0]
    for l in reversed(lines):
        low = l.lower()
        if l and ("error" in low or "not found" in low or "failed" in low
                  or "unphysical" in low):
            return l
    rest = [l for l in lines if l]
    return rest[-1] if rest else "(empty log)"


# --------------------------------------------------------------------------
# Cases
# --------------------------------------------------------------------------

def tutorial_path(tutorial):
    """Absolute path of tutorials/impactFoam/<tutorial>, or of tutorial
    itself when that is a case directory elsewhere."""
    path = os.path.join(TUTORIALS_DIR, tutorial)
    if os.path.isdir(path):
        return path
    if os.path.isdir(os.path.join(tutorial, "system")):
        return os.path.abspath(tutorial)
    raise FoamError("no tutorial %s" % path)


def copy_tutorial(tutorial, name=None, run_dir=RUN_DIR):
    """Copy a tutorial case into <run_dir>/<name> (default name: the
    tutorial's), removing an old copy first. Returns the new case path.
    Output of an earlier Allrun in the tutorial itself (mesh, time
    directories, logs) is not copied."""
    src = tutorial_path(tutorial)
    dst = os.path.join(run_dir, name or os.path.basename(src))
    if os.path.lexists(dst):
        shutil.rmtree(dst)
    os.makedirs(run_dir, exist_ok=True)

    def ignore(directory, names):
        skip = set()
        rel = os.path.relpath(directory, src)
        for n in names:
            if rel == "." and (is_time_name(n) or n.startswith("log.")
                               or n.startswith("processor")
                               or n in ("postProcessing", "VTK")):
                skip.add(n)
            if rel == "constant" and n == "polyMesh":
                skip.add(n)
        return skip

    shutil.copytree(src, dst, ignore=ignore)
    return dst


def which(app):
    """Full path of an executable on PATH, or None."""
    return shutil.which(app)


def require_apps(*apps):
    """Names of the applications (among apps) not found on PATH."""
    return [a for a in apps if shutil.which(a) is None]


def tail(path, n=30):
    """Last n lines of a text file ('' if missing)."""
    try:
        with open(path, errors="replace") as f:
            return "".join(f.readlines()[-n:])
    except OSError:
        return ""


def _case_env(case, env=None):
    """Environment for a child running in case: PWD set to the case (else
    OpenFOAM warns that PWD is not the cwd)."""
    env = dict(os.environ if env is None else env)
    env["PWD"] = os.path.abspath(case)
    return env


def run(case, cmd, log=None, timeout=None, env=None, check=True):
    """Run cmd (a list, or a string run through bash) in directory case,
    with stdout and stderr to the file case/log (default log.<application>).
    Raises FoamError carrying the log's last lines if the command fails
    (non-zero exit, timeout, or 'FOAM FATAL' in the log). Returns the log
    path."""
    if isinstance(cmd, str):
        argv = ["/bin/bash", "-c", cmd]
        app = re.sub(r"[^\w.+-]", "", os.path.basename(cmd.split()[0]))
    else:
        argv = [str(c) for c in cmd]
        app = os.path.basename(argv[0])
    logpath = os.path.join(case, log or ("log." + app))
    if isinstance(cmd, list) and shutil.which(argv[0]) is None \
            and not os.path.exists(os.path.join(case, argv[0])):
        raise FoamError("%s not found (is the environment sourced? "
                        ". etc/bashrc)" % argv[0])
    with open(logpath, "w") as logf:
        try:
            proc = subprocess.run(argv, cwd=case, stdout=logf,
                                  stderr=subprocess.STDOUT, timeout=timeout,
                                  env=_case_env(case, env))
            code = proc.returncode
        except subprocess.TimeoutExpired:
            code = None
    if not check:
        return logpath
    text = tail(logpath, 400)
    if code is None:
        why = "timed out after %s s" % timeout
    elif code != 0:
        why = "exit code %d" % code
    elif "FOAM FATAL" in text:
        why = "FOAM FATAL in log"
    else:
        return logpath
    what = " ".join(argv) if isinstance(cmd, list) else cmd
    raise FoamError("%s in %s failed (%s); last lines of %s:\n%s"
                    % (what, case, why, os.path.basename(logpath),
                       tail(logpath, 25)),
                    summary="%s failed (%s): %s"
                    % (what, why, log_summary(text)))


# --------------------------------------------------------------------------
# Dictionaries
# --------------------------------------------------------------------------

def foam_dictionary(case, dict_file, entry, value=None):
    """Read (value None) or set an entry with foamDictionary; entry may be a
    path with '/' for sub-dictionaries (e.g. 'discreteEquations/order').
    Returns the value as a string when reading."""
    path = os.path.join(case, dict_file)
    if value is None:
        argv = ["foamDictionary", "-entry", entry, "-value", path]
    else:
        argv = ["foamDictionary", "-entry", entry, "-set", str(value), path]
    proc = subprocess.run(argv, cwd=case, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True,
                          env=_case_env(case))
    if proc.returncode != 0 or "FOAM FATAL" in proc.stdout:
        raise FoamError("%s failed:\n%s" % (" ".join(argv),
                                             proc.stdout[-2000:]))
    return proc.stdout.strip() if value is None else None


def set_entry(case, dict_file, key, value, use_foam_dictionary=False):
    """Set 'key value;' in a dictionary file.

    By default a plain text edit of the first line whose first word is key
    at any depth (enough for the flat dictionaries of a tutorial: endTime,
    nx, order...), which keeps comments and layout; if no such line exists
    the entry is appended at the top level. With use_foam_dictionary, or a
    key with '/', foamDictionary -set does it."""
    if use_foam_dictionary or "/" in key:
        foam_dictionary(case, dict_file, key, value)
        return
    path = os.path.join(case, dict_file)
    with open(path) as f:
        text = f.read()
    pattern = re.compile(r"^(\s*)%s(\s+)[^;]*;" % re.escape(key), re.M)
    new, n = pattern.subn(lambda m: "%s%s%s%s;" % (m.group(1), key,
                                                   m.group(2), value),
                          text, count=1)
    if n == 0:
        new = text.rstrip("\n") + "\n\n%s %s;\n" % (key, value)
    with open(path, "w") as f:
        f.write(new)


def get_entry(case, dict_file, key):
    """Value (string) of the first 'key value;' line in a dictionary file,
    or None."""
    with open(os.path.join(case, dict_file)) as f:
        text = strip_comments(f.read())
    m = re.search(r"^\s*%s\s+([^;]*);" % re.escape(key), text, re.M)
    return m.group(1).strip() if m else None


# --------------------------------------------------------------------------
# Time directories
# --------------------------------------------------------------------------

_NUMBER = re.compile(r"^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$")


def is_time_name(name):
    return bool(_NUMBER.match(name))


def time_dirs(case):
    """Time directories of a case as a list of (time, name), ascending."""
    out = []
    for n in os.listdir(case):
        if is_time_name(n) and os.path.isdir(os.path.join(case, n)):
            out.append((float(n), n))
    return sorted(out)


def latest_time(case):
    """Name of the latest time directory."""
    dirs = time_dirs(case)
    if not dirs:
        raise FoamError("no time directories in %s" % case)
    return dirs[-1][1]


def find_time(case, t, rtol=1e-6, atol=1e-15):
    """Name of the time directory whose value is t (within tolerance);
    raises FoamError listing the available times otherwise."""
    dirs = time_dirs(case)
    for value, name in dirs:
        if abs(value - t) <= atol + rtol * abs(t):
            return name
    raise FoamError("no time directory %g in %s (have: %s)"
                    % (t, case, " ".join(n for _, n in dirs) or "none"))


# --------------------------------------------------------------------------
# Field files
# --------------------------------------------------------------------------

_NCOMP = {"scalar": 1, "vector": 3, "tensor": 9, "symmTensor": 6,
          "sphericalTensor": 1, "label": 1}

_CLASS_TYPE = {
    "volScalarField": "scalar", "volVectorField": "vector",
    "volTensorField": "tensor", "volSymmTensorField": "symmTensor",
    "volSphericalTensorField": "sphericalTensor",
    "surfaceScalarField": "scalar", "surfaceVectorField": "vector",
    "pointScalarField": "scalar", "pointVectorField": "vector",
}


def strip_comments(text):
    """Remove // and /* */ comments (not inside double-quoted strings)."""
    out = []
    i, n = 0, len(text)
    token = re.compile(r'"|//|/\*')
    while i < n:
        m = token.search(text, i)
        if not m:
            out.append(text[i:])
            break
        out.append(text[i:m.start()])
        if m.group() == '"':
            j = text.find('"', m.end())
            j = n if j < 0 else j + 1
            out.append(text[m.start():j])
            i = j
        elif m.group() == "//":
            j = text.find("\n", m.end())
            i = n if j < 0 else j
        else:
            j = text.find("*/", m.end())
            i = n if j < 0 else j + 2
            out.append(" ")
    return "".join(out)


def _read_text(path):
    if not os.path.exists(path) and os.path.exists(path + ".gz"):
        path = path + ".gz"
    if path.endswith(".gz"):
        with gzip.open(path, "rt") as f:
            return f.read()
    with open(path) as f:
        return f.read()


def _header(text):
    m = re.search(r"FoamFile\s*\{([^}]*)\}", text)
    header = {}
    if m:
        for key, val in re.findall(r"(\w+)\s+([^;]*);", m.group(1)):
            header[key] = val.strip().strip('"')
    return header


def mesh_n_cells(case, region=None):
    """Number of cells from the note of constant/polyMesh/owner
    ('nCells:N'). Returns None when it cannot be found."""
    poly = os.path.join(case, "constant", region or "", "polyMesh")
    for name in ("owner", "owner.gz"):
        path = os.path.join(poly, name)
        if os.path.exists(path):
            if name.endswith(".gz"):
                with gzip.open(path, "rt", errors="replace") as f:
                    head = f.read(4000)
            else:
                with open(path, errors="replace") as f:
                    head = f.read(4000)
            m = re.search(r"nCells\s*:\s*(\d+)", head)
            if m:
                return int(m.group(1))
    return None


def _n_cells_from_fields(time_path):
    """Number of cells from any nonuniform vol field in a time directory."""
    for name in sorted(os.listdir(time_path)):
        path = os.path.join(time_path, name)
        if not os.path.isfile(path):
            continue
        try:
            text = strip_comments(_read_text(path))
        except (OSError, UnicodeDecodeError):
            continue
        if not _header(text).get("class", "").startswith("vol"):
            continue
        m = re.search(r"internalField\s+nonuniform\s+List<\w+>\s*(\d+)", text)
        if m:
            return int(m.group(1))
    return None


def parse_field(text, n_cells=None):
    """Parse the text of an ascii OpenFOAM field file. Returns (values,
    header); values is (N,) for scalars, (N, k) for k-component types.
    A uniform internalField needs n_cells."""
    text = strip_comments(text)
    header = _header(text)
    if header.get("format", "ascii") != "ascii":
        raise FoamError("field is not ascii (format %s)" % header["format"])
    body = text[text.find("}") + 1:] if "FoamFile" in text else text
    m = re.search(r"\binternalField\s+(uniform|nonuniform)\b", body)
    if not m:
        raise FoamError("no internalField")
    rest = body[m.end():]
    end = rest.find(";")
    if end < 0:
        raise FoamError("internalField not terminated by ';'")
    rest = rest[:end]
    ftype = _CLASS_TYPE.get(header.get("class", ""))

    if m.group(1) == "uniform":
        nums = np.array(rest.replace("(", " ").replace(")", " ").split(),
                        dtype=float)
        k = nums.size
        if ftype is not None and _NCOMP[ftype] != k:
            raise FoamError("uniform value with %d components for %s"
                            % (k, header.get("class")))
        if n_cells is None:
            raise FoamError("uniform internalField: number of cells unknown")
        values = np.tile(nums, (n_cells, 1))
        return (values[:, 0] if k == 1 else values), header

    lm = re.match(r"\s*List<(\w+)>\s*", rest)
    if not lm:
        raise FoamError("nonuniform internalField without List<type>")
    ltype = lm.group(1)
    if ltype not in _NCOMP:
        raise FoamError("unsupported list type List<%s>" % ltype)
    k = _NCOMP[ltype]
    rest = rest[lm.end():]
    # "<N>(...)" or "<N>{value}" (uniform list in compact form) or "(...)"
    cm = re.match(r"(\d+)\s*\{(.*)\}\s*$", rest, re.S)
    if cm:
        n = int(cm.group(1))
        nums = np.array(cm.group(2).replace("(", " ").replace(")", " ")
                        .split(), dtype=float)
        values = np.tile(nums, (n, 1))
        return (values[:, 0] if k == 1 else values), header
    nm = re.match(r"\s*(\d+)\s*", rest)
    n = None
    if nm:
        n = int(nm.group(1))
        rest = rest[nm.end():]
    rest = rest.strip()
    if not (rest.startswith("(") and rest.endswith(")")):
        raise FoamError("malformed list in internalField")
    nums = np.array(rest.replace("(", " ").replace(")", " ").split(),
                    dtype=float)
    if n is None:
        n = nums.size // k
    if nums.size != n * k:
        raise FoamError("list of %d %s values holds %d numbers"
                        % (n, ltype, nums.size))
    values = nums.reshape(n, k)
    if n_cells is not None and n != n_cells:
        raise FoamError("field has %d values, mesh has %d cells"
                        % (n, n_cells))
    return (values[:, 0] if k == 1 else values), header


def read_field(case, time, name, n_cells=None):
    """Internal field <case>/<time>/<name> as a numpy array: (N,) scalar,
    (N, 3) vector, (N, 9) tensor (xx xy xz yx yy yz zx zy zz), (N, 6)
    symmTensor (xx xy xz yy yz zz). time is a directory name or a number
    (then matched with find_time)."""
    if not isinstance(time, str):
        time = find_time(case, time)
    path = os.path.join(case, time, name)
    try:
        text = _read_text(path)
    except OSError as e:
        raise FoamError("cannot read field %s: %s" % (path, e))
    if n_cells is None and re.search(r"\binternalField\s+uniform\b",
                                     strip_comments(text)):
        n_cells = mesh_n_cells(case) or \
            _n_cells_from_fields(os.path.join(case, time))
    try:
        values, _ = parse_field(text, n_cells)
    except FoamError as e:
        raise FoamError("%s: %s" % (path, e))
    return values


def has_field(case, time, name):
    if not isinstance(time, str):
        time = find_time(case, time)
    path = os.path.join(case, time, name)
    return os.path.isfile(path) or os.path.isfile(path + ".gz")


def cell_centres(case, time="0"):
    """Cell centres (N, 3): runs postProcess -func writeCellCentres -time t
    (once; the result C is kept in the time directory) and reads C."""
    if not isinstance(time, str):
        time = find_time(case, time)
    if not has_field(case, time, "C"):
        run(case, ["postProcess", "-func", "writeCellCentres", "-time", time],
            log="log.writeCellCentres")
    if not has_field(case, time, "C"):
        raise FoamError("postProcess -func writeCellCentres wrote no %s/C "
                        "in %s" % (time, case))
    return read_field(case, time, "C")


# --------------------------------------------------------------------------
# Components
# --------------------------------------------------------------------------

SYMM_TENSOR = {"xx": 0, "xy": 1, "xz": 2, "yy": 3, "yz": 4, "zz": 5}
TENSOR = {"xx": 0, "xy": 1, "xz": 2, "yx": 3, "yy": 4, "yz": 5,
          "zx": 6, "zy": 7, "zz": 8}
