# hsbearing -- two commands on a fresh machine with only Python 3.11+:
#   make run    create .venv, install, run the default case (archive + figure + summary)
#   make test   create .venv, install, run the tests
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed-stamp
RUN_DURATION ?= 0.7s

.PHONY: run test test-all bench clean venv

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e '.[test]'
	touch $(STAMP)

venv: $(STAMP)

run: $(STAMP)
	$(BIN)/hsbearing run --duration $(RUN_DURATION)

test: $(STAMP)
	$(BIN)/python -m pytest -q -n 2 --timeout 900

test-all: $(STAMP)
	$(BIN)/python -m pytest -q -n 2 -m "slow or not slow" --timeout 3600

bench: $(STAMP)
	$(BIN)/python -m pip install --quiet -e '.[test,bench]'
	@for f in benchmarks/bench_*.py; do echo "== $$f"; $(BIN)/python $$f || exit 1; done

clean:
	rm -rf $(VENV) build *.egg-info runs
