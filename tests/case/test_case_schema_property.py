"""a property test of the case schema (default tier, well under 60 s).

Random mutations of the bundled cases -- a value replaced by a random string, number (huge, tiny, NaN, inf),
quantity with a random unit, nested array / inline table, or raw text; a key removed; an unknown key added;
the same values given through ``--set`` -- go through ``hsbearing check`` (``cli.main`` in-process) and must
never give a traceback (an exception out of ``main``), a hang (an alarm after 20 s), a NaN printed with exit
0, or an exit 2 that is not exactly one line ``hsbearing: error: ...``.
"""

from __future__ import annotations

import json
import math
import os
import re
import signal
import tomllib

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from hsbearing import cli
from hsbearing.case import case_path, list_cases

CASES = sorted(list_cases())
TEXTS = {name: case_path(name).read_text() for name in CASES}
KEYS: dict[str, list[tuple[str, str]]] = {}  # case -> (table, key) of every scalar value, filled below


def _tables(raw: dict, prefix: str = "") -> dict[str, dict]:
    out = {}
    for k, v in raw.items():
        if isinstance(v, dict):
            full = f"{prefix}{k}"
            scalars = {kk: vv for kk, vv in v.items() if not isinstance(vv, dict)}
            if scalars:
                out[full] = scalars
            out.update(_tables(v, full + "."))
    return out


for _name in CASES:
    KEYS[_name] = [(t, k) for t, tab in _tables(tomllib.loads(TEXTS[_name])).items() for k in tab]

UNITS = ["mm", "um", "m", "in", "deg", "rad", "%", "rpm", "r/min", "rev/s", "Hz", "kHz", "1/min", "1/s", "rad/s",
         "N", "kN", "N*m", "degC", "degF", "K", "s", "ms", "GPa", "kg/m^3", "kg", "Pa*s", "mm^2/s", "", "dimensionless",
         "m**2", "m^-3", "furlong/fortnight", "bogus", "N/m"]


def _toml_number(x) -> str:
    if isinstance(x, float):
        if math.isnan(x):
            return "nan"
        if math.isinf(x):
            return "inf" if x > 0 else "-inf"
        return repr(x)
    return str(x)


numbers = st.one_of(
    st.integers(min_value=-10**30, max_value=10**30),
    st.integers().map(lambda i: i * 10**400),  # beyond float range
    st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from([0, 0.0, -0.0, 1e-320, 1e308, -1, 1, 0.5, 0.50000001, 90, 180, 1e6]),
)
quantities = st.builds(lambda x, u: json.dumps(f"{_toml_number(x)} {u}".strip()), numbers, st.sampled_from(UNITS))
strings = st.text(max_size=40).map(json.dumps)
scalars = st.one_of(numbers.map(_toml_number), quantities, strings, st.sampled_from(["true", "false"]),
                    st.just('"1979-05-27"'), st.just("1979-05-27T07:32:00Z"))
nested = st.recursive(scalars, lambda inner: st.one_of(
    st.lists(inner, max_size=3).map(lambda xs: "[" + ", ".join(xs) + "]"),
    st.dictionaries(st.from_regex(r"[a-z]{1,6}", fullmatch=True), inner, max_size=3).map(
        lambda d: "{" + ", ".join(f"{k} = {v}" for k, v in d.items()) + "}")), max_leaves=6)
raw_text = st.text(alphabet=st.characters(blacklist_categories=("Cs",), blacklist_characters="\n\r"), max_size=30)
values = st.one_of(scalars, scalars, nested, raw_text)


class _Hang(Exception):
    pass


def _alarm(signum, frame):
    raise _Hang


def _check(argv, capsys):
    """Run `hsbearing check` in-process; the contract of every outcome."""
    old = signal.signal(signal.SIGALRM, _alarm)
    signal.alarm(20)
    try:
        rc = cli.main(argv)
    except _Hang:
        pytest.fail(f"hang: {argv[:2]}")
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)
    out, err = capsys.readouterr()
    assert rc in (0, 2), (rc, err)
    assert "Traceback" not in err
    if rc == 0:
        body = out.split("\n", 1)[1] if "\n" in out else ""  # line 1 echoes the case name and path (may be "nan")
        assert not re.search(r"\bnan\b", body, re.I), out
        assert all(ln.startswith("hsbearing: warning: ") for ln in err.splitlines() if ln.strip()), err
    else:
        lines = [ln for ln in err.splitlines() if ln.strip()]
        assert len(lines) == 1 and lines[0].startswith("hsbearing: error: "), err
    return rc


@st.composite
def mutated_case(draw):
    name = draw(st.sampled_from(CASES))
    text = TEXTS[name]
    table, key = draw(st.sampled_from(KEYS[name]))
    action = draw(st.sampled_from(["replace", "replace", "replace", "remove", "unknown"]))
    lines = text.splitlines()
    # the line of table.key: the first `key =` after the `[table]` header
    start = next(i for i, ln in enumerate(lines) if re.match(rf"\s*\[{re.escape(table)}\]", ln))
    idx = next(i for i in range(start + 1, len(lines)) if re.match(rf"\s*{re.escape(key)}\s*=", lines[i]))
    if action == "replace":
        lines[idx] = f"{key} = {draw(values)}"
    elif action == "remove":
        del lines[idx]
    else:
        lines.insert(idx, f"{draw(st.from_regex(r'[a-z_]{1,12}', fullmatch=True))} = {draw(scalars)}")
    return name, "\n".join(lines) + "\n", f"{table}.{key}"


@settings(max_examples=int(os.environ.get("HSB_SCHEMA_EXAMPLES", 400)), deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture,
                                                                   HealthCheck.too_slow])
@given(mutated_case())
def test_mutated_case_file(tmp_path, capsys, case):
    name, text, _key = case
    p = tmp_path / "mutated.toml"
    p.write_text(text, encoding="utf-8", errors="surrogatepass")
    _check(["check", str(p)], capsys)


@settings(max_examples=int(os.environ.get("HSB_SCHEMA_EXAMPLES", 300)), deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture,
                                                                   HealthCheck.too_slow])
@given(st.sampled_from(CASES), st.data())
def test_mutated_override(capsys, name, data):
    table, key = data.draw(st.sampled_from(KEYS[name]))
    value = data.draw(st.one_of(values, st.text(max_size=30)))
    _check(["check", name, "--set", f"{table}.{key}={value}"], capsys)
