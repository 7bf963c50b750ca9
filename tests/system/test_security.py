"""Data never executes (issue 25): an energy text, a tube file, a sweep file and a results
store are read by whitelist grammars; nothing of them is evaluated, and what they may read
and write is bounded (docs/security.md)."""

import ast
import json
import math
import time
from pathlib import Path

import pytest
import sympy as sp

import electrogrowth
from electrogrowth import ConfigError, MaterialError
from electrogrowth.cli.app import main
from electrogrowth.model.energy_grammar import MAX_DEPTH, MAX_LENGTH, parse_energy
from electrogrowth.model.energy_text import energy_material
from electrogrowth.model.materials import INVARIANTS, Material
from electrogrowth.model.tube_file import load_tube
from electrogrowth.sweep.file import parse_config

NAMES = {str(s): s for s in INVARIANTS}
NH = "(I1 - 3)/2 + I5/2"

#: Texts that ran code, read or wrote files, or hung before the grammar; each would create
#: the file X in the working directory if it were evaluated.
INJECTIONS = [
    "__import__('os').system('touch X')",
    f"{NH} + 0*eval(\"open('X', 'w')\")",
    f"{NH} + 0*exec(\"open('X', 'w')\")",
    "open('X', 'w')",
    "I1.__class__",
    "I1.__class__.__base__.__subclasses__()",
    "__builtins__",
    "lambda: open('X', 'w')",
    "[open('X', 'w') for _ in (1,)]",
    "{open('X', 'w')}",
    "f\"{open('X', 'w')}\"",
    "'X'",
    "I1[0]",
    f"{NH}; open('X', 'w')",
    f"`{NH}`",
    "getattr(I1, 'func')",
    "globals()",
    f"{NH} if open('X', 'w') else I1",
    "(I1 - 3)/2 + I5/2 + 0*Symbol('X')",
    "ＩⅠ/2 + I5/2",  # fullwidth I, roman numeral one
    "(I1 - 3)/2\u00a0+ I5/2",  # a non-breaking space
    "(I1 - 3)/2 + I5/2 + 0*" + "I1*" * 1200 + "1",  # beyond the length limit
    "(" * 60 + "I1" + ")" * 60,  # beyond the nesting limit
    "I1,I5",
]
#: Texts the old token check let through and that then ran for minutes (or forever).
HANGS = ["0*9**9**9", "1e999999*0", "**".join(["I1"] * 41), "exp(exp(exp(exp(10))))"]
BAD = INJECTIONS + HANGS


def _one_line(exc) -> str:
    message = str(exc.value)
    assert "\n" not in message and message, message
    return message


@pytest.fixture
def empty_cwd(tmp_path, monkeypatch):
    """A fresh working directory; the test asserts it is still empty at the end."""
    work = tmp_path / "work"
    work.mkdir()
    monkeypatch.chdir(work)
    yield work
    assert sorted(p.name for p in work.iterdir()) == []


def test_the_injections_are_live(tmp_path, monkeypatch):
    """The corpus is not harmless by accident: sympify, which read these texts before,
    creates the file (so the tests below would fail if any path still used it)."""
    monkeypatch.chdir(tmp_path)
    with pytest.raises(TypeError):  # 0 * <file>, after the file was opened
        sp.sympify(INJECTIONS[1], locals=NAMES)
    assert (tmp_path / "X").exists()


# -- the parser ---------------------------------------------------------------------------

LEGAL = [
    NH,
    "0.4*(I1 - 3) + 0.1*(I2 - 3) + I5/2",
    "1/2*(I1 - 3) + I5/2",
    "(I1 - 3)/2 + I5^2/4 + I5/2 - I6/10 + I4/7",
    "-48.6*log(1 - (I1 - 3)/97.2) + I5/2",
    "(sqrt(1 + 2*(I1 - 3)) - 1)/2 + I5/2",
    "(I1 - 3)/2*exp(-(I2 - 3)/10) + I5/2 + tanh(I4) + atan(I6) + cosh(I1 - 3) - sinh(I2)",
    "-2**2*I1 + 2**-1*I5 + I1**2**3 + (I1**2)**3 + +I2 - -I4",
    "pi*E*(I1 - 3) + E**(I1 - 3) + 1e-3*I6 - .5e1*I4 + 3.*I5 + 1.5E+2*I2",
    "0.1234567890123456789*(I1 - 3) + 12345678901234567890*I4",
    "(I1 - 3)/2 + I5/2 + 0*I1/I1 + (I1 - I1)",
    "  (I1-3)/2\t+\nI5/2  ",
]


@pytest.mark.parametrize("text", LEGAL)
def test_parser_gives_what_sympify_gave(text):
    """The same expression, structurally (srepr), as today's sympify of the trusted text:
    exact Rationals stay exact, floats keep their precision, so results are bit-identical."""
    mine = parse_energy(text)
    theirs = sp.sympify(text.replace("^", "**"), locals=NAMES)
    assert sp.srepr(mine) == sp.srepr(theirs)


def test_material_text_equals_the_expression():
    a = Material("nh", NH)
    b = Material("nh", (INVARIANTS[0] - 3) / 2 + INVARIANTS[3] / 2)
    assert a.energy == b.energy and sp.srepr(a.energy) == sp.srepr(b.energy)
    assert energy_material(NH).energy == b.energy


@pytest.mark.parametrize("energy", [0.5, 1, None, b"(I1 - 3)/2 + I5/2", ["I1"], sp.Tuple(1)])
def test_material_of_another_type_is_refused(energy):
    with pytest.raises(MaterialError, match="give a sympy expression") as exc:
        Material("x", energy)
    _one_line(exc)


@pytest.mark.parametrize("text", BAD, ids=range(len(BAD)))
def test_bad_text_is_refused_in_one_line_and_runs_nothing(text, empty_cwd):
    for make in (energy_material, lambda t: Material("mine", t), parse_energy):
        start = time.perf_counter()
        with pytest.raises(MaterialError) as exc:
            make(text)
        assert time.perf_counter() - start < 1.0
        message = _one_line(exc)
        assert message.startswith("energy ") and "allowed:" in message


@pytest.mark.parametrize(
    ("text", "needle"),
    [
        ("__import__('os')", "position 1: unknown name '__import__'"),
        ("I1.real", "position 3: the character '.'"),
        ("I1,I5", "position 3: a comma: give one expression, not a list"),
        ("ＩⅠ", "position 1: the character 'Ｉ' (U+FF29) is not ASCII"),
        ("I1\u00a0+ I5", "position 3: the character '\\xa0' (U+00A0) is not ASCII"),
        ("I1 + " * 500 + "I5", f"more than the limit {MAX_LENGTH}"),
        ("(" * 60 + "I1" + ")" * 60, f"nested deeper than the limit of {MAX_DEPTH} levels"),
        ("-" * 60 + "I1", f"nested deeper than the limit of {MAX_DEPTH} levels"),
        ("I1+" * 301 + "I1", "more than the limit of 300 operations"),
        ("0*9**9**9", "a power of size about e^8.51e+08"),
        ("0.5**2000*I1", "a power of size about e^-1.39e+03"),
        ("1e999999*0", "the number 1e999999 is beyond the largest double 1.8e308"),
        ("1e-999999*I1", "below the smallest double"),
        ("**".join(["I1"] * 41), "a power of size about e^"),
        ("I4**I4**I4**I4**I4", "powers nested more than 3 deep"),
        ("(I1/3)**200", "exponents multiplied through nested powers reach 200"),
        ("((I1/3)**20)**20", "exponents multiplied through nested powers reach 400"),
        ("exp(exp(exp(exp(10))))", "exp of 2.2e+04 at the undeformed state"),
        ("cosh(1000*I1)", "cosh of 3e+03 at the undeformed state"),
        ("(10**300*I1)**3", "a power of size about e^"),
        ("10**300*10**300*I1", "numbers combine into one beyond the largest double"),
        ("1/(I1 - I1)", "a division by zero"),
        ("log(I1, 2)", "a comma"),
        ("log I1", "the function 'log' needs its argument in parentheses"),
        ("log", "the function 'log' needs its argument in parentheses"),
        ("2I1", "'I' right after the number '2'"),
        ("(I1 - 3", "the '(' at position 1 is not closed"),
        ("I1 - 3)", "a ')' without its '('"),
        ("I1 I5", "'I5' where an operator or the end is expected"),
        ("", "it is empty"),
        ("   ", "it is empty"),
    ],
)
def test_refusal_names_position_problem_and_limit(text, needle):
    with pytest.raises(MaterialError) as exc:
        parse_energy(text)
    assert needle in _one_line(exc)


def test_long_text_is_shortened_in_the_message():
    with pytest.raises(MaterialError) as exc:
        parse_energy("I1 + " * 500 + "x")
    assert len(_one_line(exc)) < 300 and "..." in str(exc.value)


def test_a_legal_energy_that_overflows_is_one_error_and_no_warning(recwarn):
    """exp((I1 - 3)^3) is finite at the undeformed state but not at lambda = 20: one
    ParameterError naming the deformation, no NumPy RuntimeWarning."""
    mat = energy_material(f"{NH} + exp((I1 - 3)**3) - 1")
    for evaluate in (mat.stress, mat.moduli, mat.electric_field):
        with pytest.raises(electrogrowth.ParameterError, match="outside the domain"):
            evaluate(20.0, 1 / 20, 1.0, 0.0)
    assert not [w for w in recwarn if issubclass(w.category, RuntimeWarning)]


def test_cli_overflowing_energy_prints_no_warning(capsys):
    """At g = 7 the homogeneous state has I1 - 3 = 11.0, where exp((I1 - 3)^3) overflows:
    no state, one line, no warning. (At g = 3, I1 - 3 = 3.1 and the energy exp(30) is
    finite: that state exists and is printed, lambda_i = sqrt(g^3 / lambda_z).)"""
    argv = ["state", "--outer-radius", "1.4", "--energy", f"{NH} + exp((I1 - 3)**3) - 1"]
    assert main([*argv, "--growth", "7"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Warning" not in err, err
    assert main([*argv, "--growth", "3", "--json"]) == 0
    out, err = capsys.readouterr()
    assert json.loads(out)["lambda_i"] == pytest.approx(27**0.5, rel=1e-12) and not err


# -- the property: random legal expressions ----------------------------------------------

hypothesis = pytest.importorskip("hypothesis")
from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

COMMON = dict(deadline=None, derandomize=True, database=None)

numbers = st.one_of(
    st.integers(0, 50).map(str),
    st.sampled_from(["0.5", "1.25", "2.0", ".75", "1e-3", "3.5e1", "0.1"]),
)
atoms = st.one_of(numbers, st.sampled_from([*NAMES, "pi", "E"]))


def _combine(children):
    binary = st.tuples(children, st.sampled_from(["+", "-", "*", "/"]), children).map(
        lambda t: f"({t[0]} {t[1]} {t[2]})" if t[1] != "/" else f"({t[0]})/({t[2]} + 7)"
    )
    power = st.tuples(children, st.sampled_from(["2", "3", "-1", "(1/2)", "0.5"])).map(
        lambda t: f"(({t[0]}) + 4)**{t[1]}"
    )
    xor = children.map(lambda c: f"({c})^2")
    unary = st.tuples(st.sampled_from(["-", "+"]), children).map(lambda t: f"{t[0]}({t[1]})")
    call = st.tuples(
        st.sampled_from(["log", "exp", "sqrt", "tanh", "atan", "cosh", "sinh"]), children
    ).map(lambda t: f"{t[0]}(({t[1]})/100 + 2)")
    return st.one_of(binary, power, xor, unary, call)


LIMITS = (
    "powers nested",
    "exponents multiplied",
    "a power of size",
    "exp of",
    "cosh of",
    "sinh of",
    "numbers combine",
    "not finite",
    "division by zero",
)
expressions = st.recursive(atoms, _combine, max_leaves=12)


def _check_same(text):
    theirs = sp.sympify(text.replace("^", "**"), locals=NAMES)
    try:
        mine = parse_energy(text)
    except MaterialError as exc:
        # only a limit may refuse a text of the grammar (sympify's result is then out of
        # range or not finite), never the grammar itself
        assert any(reason in str(exc) for reason in LIMITS), str(exc)
        return
    assert sp.srepr(mine) == sp.srepr(theirs), text


@settings(max_examples=25, **COMMON)
@given(text=expressions)
def test_random_legal_expressions_parse_as_sympify_did(text):
    _check_same(text)


@pytest.mark.slow
@settings(max_examples=1000, **COMMON)
@given(text=expressions)
def test_random_legal_expressions_parse_as_sympify_did_many(text):
    _check_same(text)


# -- every path that reads an energy -------------------------------------------------------

STATE = ["state", "--outer-radius", "1.4", "--growth", "1.1"]


def _cli_refuses(argv, capsys, *needles):
    assert main(argv) == 2
    captured = capsys.readouterr()
    err = captured.err
    assert err.count("\n") == 1 and err.startswith("electrogrowth: error: "), err
    assert "Traceback" not in err and captured.out == ""
    for needle in needles:
        assert needle in err, err
    return err


@pytest.mark.parametrize("text", BAD, ids=range(len(BAD)))
def test_cli_energy_refuses(text, empty_cwd, capsys):
    start = time.perf_counter()
    _cli_refuses([*STATE, "--energy", text], capsys, "energy")
    assert time.perf_counter() - start < 1.0


def _tube_file(folder: Path, energy: str, name: str = "tube.toml") -> Path:
    path = folder / name
    path.write_text(
        f"voltage = 0.1\n[[layers]]\nouter_radius = 1.4\nenergy = {json.dumps(energy)}\n",
        encoding="utf-8",
    )
    return path


@pytest.mark.parametrize("text", BAD, ids=range(len(BAD)))
def test_tube_file_energy_refuses(text, tmp_path, empty_cwd, capsys):
    tube = _tube_file(tmp_path, text)
    start = time.perf_counter()
    _cli_refuses(["state", "--tube", str(tube)], capsys, "tube.toml:4: layers.1.energy:")
    assert time.perf_counter() - start < 1.0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["tube.toml", "work"]


SWEEP = """\
[solve]
for = "growth"
[modes]
m = [0, 2]
n = [1, 2]
extend = false
[material]
energy = {energy}
[fixed]
outer_radius = 1.4
[grid]
voltage = [0.0]
"""
TUBE_SWEEP = """\
[solve]
for = "growth"
[modes]
m = [0, 2]
n = [1, 2]
extend = false
[tube]
file = {file}
[grid]
voltage = [0.0]
"""
SOME = [BAD[0], BAD[1], BAD[19], BAD[23], *HANGS[:3]]


@pytest.mark.parametrize("text", SOME, ids=range(len(SOME)))
@pytest.mark.parametrize("check", [True, False], ids=["check", "run"])
def test_sweep_file_energy_refuses(text, check, tmp_path, empty_cwd, capsys):
    sweep = tmp_path / "s.toml"
    sweep.write_text(SWEEP.format(energy=json.dumps(text)), encoding="utf-8")
    out = tmp_path / "s.zarr"
    argv = ["sweep", str(sweep), "--out", str(out), "--quiet", *(["--check"] if check else [])]
    _cli_refuses(argv, capsys, "s.toml:8: material.energy: energy")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s.toml", "work"]


@pytest.mark.parametrize("text", SOME, ids=range(len(SOME)))
@pytest.mark.parametrize("check", [True, False], ids=["check", "run"])
def test_sweep_tube_file_energy_refuses(text, check, tmp_path, empty_cwd, capsys):
    _tube_file(tmp_path, text)
    sweep = tmp_path / "s.toml"
    sweep.write_text(TUBE_SWEEP.format(file='"tube.toml"'), encoding="utf-8")
    out = tmp_path / "s.zarr"
    argv = ["sweep", str(sweep), "--out", str(out), "--quiet", *(["--check"] if check else [])]
    _cli_refuses(argv, capsys, "tube.file:", "layers.1.energy: energy")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s.toml", "tube.toml", "work"]


# -- a results store whose configuration was tampered with -------------------------------

pytest.importorskip("zarr")


def _store(tmp_path: Path, sweep_text: str) -> Path:
    """A store of a legal sweep (created, nothing computed), as `sweep` writes it."""
    from electrogrowth.sweep.store import open_store

    out = tmp_path / "s.zarr"
    open_store(out, parse_config(sweep_text, source=str(tmp_path / "s.toml")))
    return out


def _tamper(store: Path, edit) -> None:
    """Edit the stored configuration in the root metadata file, as an attacker would."""
    meta = store / "zarr.json"
    root = json.loads(meta.read_text())
    config = json.loads(root["attributes"]["sweep_config"])
    edit(config)
    root["attributes"]["sweep_config"] = json.dumps(config)
    meta.write_text(json.dumps(root))


def _set_energy(text):
    return lambda config: config["material"].update(energy=text)


def _set_tube_energy(text):
    def edit(config):
        original = config["tube"]["text"]
        config["tube"]["text"] = original.replace(json.dumps(NH), json.dumps(text))
        assert config["tube"]["text"] != original

    return edit


def _files(folder: Path) -> list[str]:
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*"))


@pytest.mark.parametrize("text", SOME, ids=range(len(SOME)))
@pytest.mark.parametrize("layered", [False, True], ids=["material", "tube"])
def test_tampered_store_is_refused_everywhere(text, layered, tmp_path, empty_cwd, capsys):
    from electrogrowth.errors import SweepError
    from electrogrowth.sweep.store import open_results, read_config

    if layered:
        _tube_file(tmp_path, NH)
        sweep_text = TUBE_SWEEP.format(file='"tube.toml"')
    else:
        sweep_text = SWEEP.format(energy=json.dumps(NH))
    (tmp_path / "s.toml").write_text(sweep_text, encoding="utf-8")
    store = _store(tmp_path, sweep_text)
    read_config(store)  # the legal store reads back
    _tamper(store, _set_tube_energy(text) if layered else _set_energy(text))
    before = _files(tmp_path)
    for read in (read_config, open_results):
        start = time.perf_counter()
        with pytest.raises(SweepError) as exc:
            read(store)
        assert time.perf_counter() - start < 2.0
        message = _one_line(exc)
        assert "unreadable sweep configuration" in message and "energy" in message
    plots = tmp_path / "plots"
    _cli_refuses(["plot", str(store), "--out", str(plots)], capsys, "s.zarr")
    resume = ["sweep", str(tmp_path / "s.toml"), "--out", str(store), "--quiet"]
    _cli_refuses(resume, capsys, "s.zarr")
    _cli_refuses([*resume, "--check"], capsys, "s.zarr")
    assert _files(tmp_path) == before  # nothing written, not even the plot folder


@pytest.mark.parametrize(
    "stored",
    [
        "[" * 100_000 + "]" * 100_000,
        "not json",
        json.dumps({"material": {"energy": ["I1"]}}),
        json.dumps([1, 2]),
        json.dumps("__import__('os').system('touch X')"),
    ],
    ids=["deep", "not-json", "energy-list", "list", "string"],
)
def test_store_with_a_malformed_configuration_is_one_line(stored, tmp_path, empty_cwd):
    from electrogrowth.errors import SweepError
    from electrogrowth.sweep.store import open_results

    store = _store(tmp_path, SWEEP.format(energy=json.dumps(NH)))
    meta = store / "zarr.json"
    root = json.loads(meta.read_text())
    root["attributes"]["sweep_config"] = stored
    meta.write_text(json.dumps(root))
    with pytest.raises(SweepError, match="unreadable sweep configuration") as exc:
        open_results(store)
    _one_line(exc)


def test_nothing_in_the_package_evaluates_or_unpickles():
    """No call of eval, exec, compile, sympify, parse_expr, literal_eval or a pickle load,
    and no allow_pickle, anywhere in the package's source (lambdify's own code generation
    works on sympy trees built by the grammar, never on text)."""
    builtins = {"eval", "exec", "compile"}
    parsers = {"sympify", "parse_expr", "literal_eval", "S"}
    found = []
    for path in Path(electrogrowth.__file__).parent.rglob("*.py"):
        source = path.read_text(encoding="utf-8")
        if "allow_pickle" in source or "import pickle" in source or "marshal" in source:
            found.append(f"{path.name}: pickle")
        for node in ast.walk(ast.parse(source)):
            if not isinstance(node, ast.Call):
                continue
            f, name = node.func, ast.unparse(node.func)
            if (
                (isinstance(f, ast.Name) and f.id in builtins)
                or name.split(".")[-1] in parsers
                or (name.split(".")[-1] in ("load", "loads") and "pickle" in name)
            ):
                found.append(f"{path.name}:{node.lineno}: {name}")
    assert found == []


# -- paths: what a sweep file may read, where a sweep writes ------------------------------


def test_tube_file_path_resolves_against_the_sweep_file(tmp_path, empty_cwd):
    """A relative [tube] file is read from the sweep file's folder (not the working
    directory); `..` may leave it, and an absolute path is read as given: the file is only
    read, and its text is copied into the configuration."""
    folder = tmp_path / "a"
    (folder / "tubes").mkdir(parents=True)
    (folder / "sweeps").mkdir()
    tube = _tube_file(folder / "tubes", NH, "t.toml")
    decoy = _tube_file(empty_cwd, "(I1 - 3)/2 + I5/2 + I6/10", "t.toml")
    source = folder / "sweeps" / "s.toml"
    for file in ('"../tubes/t.toml"', json.dumps(str(tube))):
        config = parse_config(TUBE_SWEEP.format(file=file), source=str(source))
        assert config.tube == tube.read_text()
    with pytest.raises(ConfigError, match="s.toml:8: tube.file: .*sweeps/t.toml: cannot read"):
        parse_config(TUBE_SWEEP.format(file='"t.toml"'), source=str(source))
    decoy.unlink()


@pytest.mark.parametrize(
    ("target", "needle"),
    [
        ("/dev/zero", "not a regular file"),
        (".", "is a directory"),
        ("big.toml", "more than the limit 1000000"),
        ("missing.toml", "cannot read the tube file"),
    ],
)
def test_tube_file_that_is_no_file_is_refused_before_reading(target, needle, tmp_path):
    (tmp_path / "big.toml").write_text("# " + "x" * 1_000_000 + "\n")
    start = time.perf_counter()
    with pytest.raises(ConfigError, match=needle) as exc:
        parse_config(TUBE_SWEEP.format(file=json.dumps(target)), source=str(tmp_path / "s.toml"))
    assert time.perf_counter() - start < 1.0
    _one_line(exc)
    with pytest.raises(ConfigError, match=needle):
        load_tube(target if target.startswith("/") else tmp_path / target)


def test_a_sweep_writes_only_its_out_store(tmp_path, empty_cwd, capsys):
    """A one-point sweep (computed) writes its store under --out and nothing else: not in
    the working directory, not next to the sweep or tube file."""
    inputs = tmp_path / "inputs"
    inputs.mkdir()
    _tube_file(inputs, NH)
    sweep = inputs / "s.toml"
    sweep.write_text(TUBE_SWEEP.format(file='"tube.toml"'), encoding="utf-8")
    out = tmp_path / "results" / "s.zarr"
    before = _files(tmp_path)
    assert main(["sweep", str(sweep), "--out", str(out), "--workers", "1", "--quiet"]) == 0
    capsys.readouterr()
    after = _files(tmp_path)
    new = [p for p in after if p not in before]
    assert new and all(p == "results" or p.startswith("results/s.zarr") for p in new), new
    from electrogrowth.sweep.store import open_results

    ds = open_results(out)
    assert str(ds["status"].values.ravel()[0]) == "ok"
    assert math.isfinite(float(ds["critical_value"].values.ravel()[0]))


@pytest.mark.parametrize(
    ("text", "ideal"),
    [
        (NH, True),
        ("-48.6*log(1 - (I1 - 3)/97.2) + I5/2", True),
        (f"{NH} + I6/10 - I5/10", False),
        (f"{NH} + cosh(I4)**2 - sinh(I4)**2 - 1", True),  # zero only after simplify
        (f"{NH} + (I4 + I6)**2*exp(I1 - 3)", False),
    ],
)
def test_ideal_dielectric_check(text, ideal):
    assert Material("x", text).is_ideal_dielectric() is ideal


def test_ideal_dielectric_check_of_a_long_energy_is_fast():
    """A 1000-character energy from a file: simplify took 20 s to say it is not ideal; a
    derivative that is clearly non-zero at a sample point says it at once."""
    term = "1e-3*(sinh(exp(I1/10 + I2/10)/3 + 1) - sinh(exp(3/5)/3 + 1))*(I4 + I6)**2"
    mat = Material("x", " + ".join([NH] + [term.replace("10", str(10 + k)) for k in range(12)]))
    start = time.perf_counter()
    assert not mat.is_ideal_dielectric()
    assert time.perf_counter() - start < 3.0


# -- quantities on the command line ---------------------------------------------------------


@pytest.mark.parametrize(
    "text",
    ["2.8 mm*9**9**9", "2.8 mm**9**9", "2.8 mm + __import__('os')", "2.8 mm; ls", "2.8 mm" * 30],
)
def test_quantity_text_outside_its_grammar_is_refused_before_pint(text, empty_cwd, capsys):
    """pint evaluates arithmetic: `--outer-radius "2.8 mm*9**9**9"` ran forever."""
    pytest.importorskip("pint")
    start = time.perf_counter()
    argv = ["state", "--inner-radius", "2mm", "--outer-radius", text]
    _cli_refuses(argv, capsys, "--outer-radius = ", "is not a quantity")
    assert time.perf_counter() - start < 1.0


@pytest.mark.parametrize(
    ("text", "si"),
    [("2.8 mm", 2.8e-3), ("2.8mm", 2.8e-3), ("0.28 cm", 2.8e-3), ("1e-3 km", 1.0)],
)
def test_quantity_text_in_the_grammar_is_read(text, si):
    pytest.importorskip("pint")
    from electrogrowth.model.units import magnitude

    assert magnitude(text, "outer radius", "length", "m") == pytest.approx(si, rel=1e-12)
    assert magnitude("4.16e-11 F/m", "eps", "permittivity", "F/m") == pytest.approx(4.16e-11)
    assert magnitude("3 N/m^2", "p", "pressure", "Pa") == pytest.approx(3.0)
    assert magnitude("3 N * m**-2", "p", "pressure", "Pa") == pytest.approx(3.0)


# -- numbers and sizes in TOML files --------------------------------------------------------

TUBE_TOP = "[[layers]]\nouter_radius = 1.4\n"


@pytest.mark.parametrize(
    ("text", "needle"),
    [
        ("length = " + "1" * 5000 + "\n" + TUBE_TOP, "an integer of more than 4300 digits"),
        ("length = " + "1" * 400 + "\n" + TUBE_TOP, "length: 1111"),
        (TUBE_TOP + "growth = [" + "1" * 400 + ", 1, 1]\n", "layers.1.growth: 1111"),
        ("length = " + "[" * 100_000 + "]" * 100_000 + "\n", "nested too deeply"),
        ("length = '" + "x" * 10_000 + "'\n" + TUBE_TOP, "length: expected a number"),
    ],
    ids=["5000-digits", "400-digits", "400-digit-growth", "deep", "long-string"],
)
def test_tube_file_numbers_beyond_doubles_are_one_line(text, needle, tmp_path, capsys):
    """These were "internal error: OverflowError/ValueError/RecursionError"."""
    path = tmp_path / "t.toml"
    path.write_text(text)
    err = _cli_refuses(["state", "--tube", str(path)], capsys, needle)
    assert len(err) < 400, err  # a huge value is shortened


@pytest.mark.parametrize(
    ("grid", "needle"),
    [
        ("voltage = {start = 0.0, stop = 1.0, num = 1000000000000}", "need 1 <= num <= 1000000"),
        ("voltage = [0.0, " + "1" * 400 + "]", "is not a finite number"),
        (
            "voltage = {start = 0.0, stop = 0.1, num = 10000}\n"
            "length = {start = 1.0, stop = 2.0, num = 10000}",
            "1e+08 grid points, more than the limit 1e+07",
        ),
    ],
)
def test_sweep_grid_beyond_the_limits_is_refused_at_once(grid, needle, tmp_path, capsys):
    """num = 1e12 would have allocated 8 TB before any check."""
    text = SWEEP.format(energy=json.dumps(NH)).replace("voltage = [0.0]", grid)
    path = tmp_path / "s.toml"
    path.write_text(text)
    start = time.perf_counter()
    _cli_refuses(["sweep", str(path), "--check"], capsys, needle)
    assert time.perf_counter() - start < 2.0


# -- what a store's arrays can do ------------------------------------------------------------


class _Payload:
    """Unpickling this creates the file X in the working directory."""

    def __reduce__(self):
        import os

        return (os.system, ("touch X",))


def test_store_with_a_pickled_array_is_refused_and_runs_nothing(tmp_path, empty_cwd, capsys):
    """A Zarr v2 store whose object array declares the pickle codec: the package opens only
    v3 stores (which it writes), and zarr itself refuses the pickle dtype; neither unpickles."""
    import pickle

    import numpy as np

    from electrogrowth.errors import SweepError
    from electrogrowth.sweep.store import _coordinates, open_results

    config = parse_config(SWEEP.format(energy=json.dumps(NH)))
    ds = _coordinates(config, "")
    ds["status"] = ("voltage", np.array(["ok"], dtype=object))
    store = tmp_path / "v2.zarr"
    ds.to_zarr(store, zarr_format=2, mode="w")
    meta_path = store / "status" / ".zarray"
    meta = json.loads(meta_path.read_text())
    meta.update(filters=[{"id": "pickle"}], compressor=None)
    meta_path.write_text(json.dumps(meta))
    payload = np.empty(1, dtype=object)
    payload[0] = _Payload()
    (store / "status" / "0").write_bytes(pickle.dumps(payload))
    with pytest.raises(SweepError) as exc:
        open_results(store)
    _one_line(exc)
    _cli_refuses(["plot", str(store), "--out", str(tmp_path / "plots")], capsys, "v2.zarr")
    assert not (tmp_path / "plots").exists()


def test_store_with_a_damaged_chunk_is_one_line(tmp_path, empty_cwd, capsys):
    """A chunk file that is not what its codecs say: "cannot be read", exit 2 (it was an
    internal error)."""
    from electrogrowth.errors import SweepError
    from electrogrowth.sweep.store import open_results

    store = _store(tmp_path, SWEEP.format(energy=json.dumps(NH)))
    chunk = store / "status" / "c" / "0"
    chunk.parent.mkdir(parents=True)
    chunk.write_bytes(b"\x00garbage" * 10)
    with pytest.raises(SweepError, match="s.zarr cannot be read") as exc:
        open_results(store)
    _one_line(exc)
    _cli_refuses(["plot", str(store), "--out", str(tmp_path / "plots")], capsys, "cannot be read")
