# electrogrowth developer tasks. Needs only GNU make and python3 (>= 3.11):
# the first target run creates the virtualenv $(VENV) and installs the package into it.

PYTHON ?= python3
VENV ?= .venv
BIN := $(VENV)/bin
OUT ?= out

.PHONY: install test test-slow lint format demo bench bench-ab figures docs clean distclean

# Re-install only when pyproject.toml changes (the stamp is older than it).
$(VENV)/.installed: pyproject.toml
	@echo "electrogrowth: creating the virtualenv $(VENV)"
	$(PYTHON) -m venv $(VENV)
	@echo "electrogrowth: installing the package and its tools into $(VENV) (1-3 min)"
	$(BIN)/python -m pip install -q --upgrade pip
	$(BIN)/python -m pip install -q -e '.[test,lint,vtk,sweep,units,fe]'
	touch $@

# The compiled kernels. numba keys a cached kernel on its own file only: a kernel whose
# callee, or a constant it reads (another file's tableau or index map), changed would keep
# running the old code. So a change to any source file drops the whole cache, and the
# kernels are compiled again now (cache=True keeps them), not at a user's first call. They
# do not depend on the energy: gent, mooney-rivlin and --energy load this cache
# (NUMBA_DEBUG_CACHE=1), and an energy's own derivatives take ~0.1 s per process.
KERNEL_SOURCES := $(shell find src -name '*.py')
$(VENV)/.kernels: $(KERNEL_SOURCES) | $(VENV)/.installed
	find src -name '*.nbi' -delete -o -name '*.nbc' -delete
	@echo "electrogrowth: compiling the numerical kernels (2-5 min, once per change; kept in the cache)"
	$(BIN)/electrogrowth critical --solve-for growth --outer-radius 1.4 --length 1 \
		--voltage 0.4 > /dev/null
	$(BIN)/electrogrowth critical --tube examples/bilayer.toml --solve-for voltage \
		--mode 0 1 > /dev/null
	touch $@

# The heavier optional extras (sweep = xarray/zarr/dask, vtk = meshio), on demand.
$(VENV)/.installed-%: $(VENV)/.installed
	@echo "electrogrowth: installing the optional extra '$*' into $(VENV)"
	$(BIN)/python -m pip install -q -e '.[test,$*]'
	touch $@

install: $(VENV)/.kernels

# The lint and format checks first (seconds), then the tests and every docstring example.
# Two processes (pytest-xdist; JOBS=4 on a larger machine), then the tests that time real
# signals to child processes, alone: beside another process they were flaky.
JOBS ?= 2
test: lint $(VENV)/.kernels
	$(BIN)/python -m pytest -q -n $(JOBS) -m 'not slow and not serial'
	$(BIN)/python -m pytest -q -m 'serial and not slow'

# Exit status 5 (no test selected) is not a failure while no test is marked slow.
# ruff: the lint rules and the formatting of pyproject.toml [tool.ruff]; changes nothing.
# mypy: the types of the public API (pyproject.toml [tool.mypy]; ~30 s cold, ~2 s cached).
lint: $(VENV)/.installed
	$(BIN)/ruff check src tests benchmarks tools examples docs/conf.py docs/_ext
	$(BIN)/ruff format --check src tests benchmarks tools examples docs/conf.py docs/_ext
	$(BIN)/mypy

# Apply ruff's safe fixes and its formatting.
format: $(VENV)/.installed
	$(BIN)/ruff check --fix src tests benchmarks tools examples docs/conf.py docs/_ext
	$(BIN)/ruff format src tests benchmarks tools examples docs/conf.py docs/_ext

test-slow: $(VENV)/.kernels
	$(BIN)/python -m pytest -q -n $(JOBS) -m slow || [ $$? -eq 5 ]

demo: $(VENV)/.kernels
	$(BIN)/electrogrowth demo --out $(OUT)
	@echo ""
	@echo "The command is $(BIN)/electrogrowth. To type just 'electrogrowth' in this shell:"
	@echo "    . $(BIN)/activate"
	@echo "then e.g. 'electrogrowth --help' or 'electrogrowth critical --help'."

# The suite (benchmarks/bench.py): tables into BENCHMARKS.md, benchmarks/results.json.
# About an hour on the 2-core machine; make bench BENCH_ARGS=--quick checks that it runs.
bench: $(VENV)/.kernels
	$(BIN)/python benchmarks/bench.py $(BENCH_ARGS)

# This checkout against BASE (a git revision) on the same points, in alternating fresh
# processes: make bench-ab BASE=<revision>. About 40 minutes; BENCH_ARGS=--quick to check it runs.
bench-ab: $(VENV)/.kernels
	$(BIN)/python benchmarks/ab.py $(BASE) $(BENCH_ARGS)

figures: $(VENV)/.kernels
	$(BIN)/electrogrowth reproduce --out $(OUT)/figures

# The documentation site in docs/_build/html (Sphinx, the gallery runs every example; the
# docs extra). -W: a warning fails the build.
# Sphinx reports each page and each gallery example as it goes (no -q).
docs: $(VENV)/.installed-docs
	@echo "electrogrowth: building the documentation; every gallery example runs (minutes)"
	$(BIN)/python -m sphinx -W --keep-going -b html docs docs/_build/html
	@echo "open docs/_build/html/index.html"

clean:
	rm -rf $(OUT) build .pytest_cache .mypy_cache src/*.egg-info docs/_build docs/gallery
	find . -path ./$(VENV) -prune -o -name __pycache__ -type d -prune -exec rm -rf {} +

# clean, and also remove the virtualenv.
distclean: clean
	rm -rf $(VENV)
