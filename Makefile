# hsbearing -- two commands on a fresh machine with only Python 3.11+:
#   make run    create .venv, install the locked dependencies, run the default case (archive + figure + summary)
#   make test   create .venv, install the locked dependencies, run the tests
# The exact versions live in requirements.lock (pip-compile of pyproject.toml with the test and bench extras);
# pyproject.toml keeps the loose ranges for library users.  `make lock` refreshes the lock,
# `make test-latest` runs the suite against the newest versions the ranges allow (in .venv-latest, not in CI).
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed-stamp
LATEST := .venv-latest
RUN_DURATION ?= 0.7s
PYTEST_ARGS ?=

.PHONY: run test test-all test-latest bench lock lint mutation clean venv

$(STAMP): pyproject.toml requirements.lock
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -r requirements.lock
	$(BIN)/python -m pip install --quiet --no-deps -e .
	touch $(STAMP)

venv: $(STAMP)

run: $(STAMP)
	$(BIN)/hsbearing run --duration $(RUN_DURATION)

# pytest exit 5 = the selection holds no test (e.g. PYTEST_ARGS="-k nothing"): reported, not a failure
test: $(STAMP)
	@rc=0; $(BIN)/python -m pytest -q -n 2 --timeout 900 $(PYTEST_ARGS) || rc=$$?; \
	if [ $$rc -eq 5 ]; then echo "make test: no test selected (pytest exit 5)"; rc=0; fi; exit $$rc

test-all: $(STAMP)
	$(BIN)/python -m pytest -q -n 2 -m "slow or not slow" --timeout 3600 $(PYTEST_ARGS)

# The newest versions pyproject.toml allows, in a venv of its own; not part of CI.
test-latest:
	$(PYTHON) -m venv $(LATEST)
	$(LATEST)/bin/python -m pip install --quiet --upgrade pip
	$(LATEST)/bin/python -m pip install --quiet --upgrade --upgrade-strategy eager -e '.[test]'
	$(LATEST)/bin/python -m pip freeze --exclude-editable > $(LATEST)/versions.txt
	$(LATEST)/bin/python -m pytest -q -n 2 --timeout 900 -p no:cacheprovider $(PYTEST_ARGS)

# Regenerate requirements.lock from pyproject.toml (pip-tools, installed into .venv on demand).
lock: $(STAMP)
	$(BIN)/python -m pip install --quiet pip-tools
	$(BIN)/pip-compile --quiet --upgrade --extra test --extra bench --strip-extras --no-emit-find-links \
	    --no-emit-index-url --no-emit-trusted-host -o requirements.lock pyproject.toml

# ruff over the package, tests, tools, benchmarks and docs scripts (rules: [tool.ruff] in pyproject.toml; ruff is in the lock)
lint: $(STAMP)
	$(BIN)/ruff check hsbearing tests tools benchmarks docs

# the mutation check: each plausible one-line bug of tools/investigations/mutation_check.py applied to a copy of the
# package, the validation tests covering that file run against it (fresh numba cache each); the baseline must pass and
# every mutation must be caught (docs/testing.md, "Mutation check across the physics"; ~31 min on 2 cores, not in CI)
mutation: $(STAMP)
	$(BIN)/python tools/investigations/mutation_check.py

# every benchmark in benchmarks/ (one-off measurements live in tools/investigations/)
bench: $(STAMP)
	@for f in benchmarks/bench_*.py; do echo "== $$f"; $(BIN)/python $$f || exit 1; done

clean:
	rm -rf $(VENV) $(LATEST) build *.egg-info runs
