# hsbearing -- two commands on a fresh machine with only Python 3.11+:
#   make run    create .venv, install the locked dependencies, run the default case (archive + figure + summary)
#   make test   create .venv, install the locked dependencies, run the tests
#   make docs   the documentation site (Sphinx, pinned in requirements-docs.lock) into docs/_build/html
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

.PHONY: run test test-all test-latest bench lock lock-docs lint mutation clean venv docs browser

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

# The docs site: Sphinx + MyST Markdown + autodoc/autosummary + sphinx-argparse + sphinx-gallery, the versions pinned in
# requirements-docs.lock (installed into .venv on demand). Warnings are errors (-W, kept going to list them all),
# -n checks the cross-references between pages, tools/check_docs_links.py every relative link and anchor of the
# built HTML. The gallery is rendered, not executed (HSBEARING_DOCS_RUN_EXAMPLES=1 executes it; the slow tier
# runs every example script: tests/test_examples.py).
DOCS_STAMP := $(VENV)/.docs-stamp
$(DOCS_STAMP): $(STAMP) requirements-docs.lock
	$(BIN)/python -m pip install --quiet -r requirements-docs.lock
	touch $(DOCS_STAMP)

docs: $(DOCS_STAMP)
	rm -rf docs/_build docs/reference/generated docs/auto_examples
	$(BIN)/python -m sphinx -b html -n -W --keep-going -q docs docs/_build/html
	$(BIN)/python tools/check_docs_links.py docs/_build/html

# Regenerate requirements.lock from pyproject.toml (pip-tools, installed into .venv on demand).
lock: $(STAMP)
	$(BIN)/python -m pip install --quiet pip-tools
	$(BIN)/pip-compile --quiet --upgrade --extra test --extra bench --strip-extras --no-emit-find-links \
	    --no-emit-index-url --no-emit-trusted-host -o requirements.lock pyproject.toml

# Regenerate requirements-docs.lock (the docs extra, constrained to requirements.lock's versions)
lock-docs: $(STAMP)
	$(BIN)/python -m pip install --quiet pip-tools
	$(BIN)/pip-compile --quiet --upgrade --strip-extras --no-emit-find-links --no-emit-index-url \
	    --no-emit-trusted-host -o requirements-docs.lock requirements-docs.in

# ruff over the package, tests, tools, benchmarks and docs scripts (rules: [tool.ruff] in pyproject.toml; ruff is in the lock)
lint: $(STAMP)
	$(BIN)/ruff check hsbearing tests tools benchmarks docs examples

# the mutation check: each plausible one-line bug of tools/investigations/mutation_check.py applied to a copy of the
# package, the validation tests covering that file run against it (fresh numba cache each); the baseline must pass and
# every mutation must be caught (docs/testing.md, "Mutation check across the physics"; ~31 min on 2 cores, not in CI)
mutation: $(STAMP)
	$(BIN)/python tools/investigations/mutation_check.py

# every benchmark in benchmarks/ (one-off measurements live in tools/investigations/)
bench: $(STAMP)
	@for f in benchmarks/bench_*.py; do echo "== $$f"; $(BIN)/python $$f || exit 1; done

# Debian's headless chromium for the slow-tier browser test of the compare page (tests/workflows/test_compare_browser.py,
# which runs this target when no chromium is found); needs root and apt (CI and the developers' machines are root)
browser:
	@command -v chromium >/dev/null 2>&1 || { apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends chromium >/dev/null; }
	@command -v chromium

clean:
	rm -rf $(VENV) $(LATEST) build *.egg-info runs docs/_build docs/reference/generated docs/auto_examples
