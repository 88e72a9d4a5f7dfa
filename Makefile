# The two entry points of the README. Both create .venv themselves.
PY ?= python3.11
VENV := .venv
BIN := $(VENV)/bin

.PHONY: run test lint bench docs clean

$(BIN)/ncvm: pyproject.toml
	@command -v $(PY) >/dev/null 2>&1 || { echo "python3.11 not found; set PY=python3"; exit 2; }
	$(PY) -m venv $(VENV)
	$(BIN)/pip install -q --upgrade pip
	$(BIN)/pip install -q -e '.[test,cluster,frames]'
	@touch $@

# Run every program in examples/ on the built-in default machine, one plot each into out/.
run: $(BIN)/ncvm
	@mkdir -p out
	$(BIN)/python examples/run_all.py --out out

test: $(BIN)/ncvm
	$(BIN)/ruff check src tests bench examples
	$(BIN)/python -m pytest

bench: $(BIN)/ncvm
	$(BIN)/python bench/run.py

# Regenerate the machine-file reference (docs/machine-file.md tables, docs/machine-file.schema.json) and the
# control profiles' G tables (docs/profiles.md).
docs: $(BIN)/ncvm
	$(BIN)/python -m ncvm.machine.docgen
	$(BIN)/python -m ncvm.nc.profiles.doc

clean:
	rm -rf $(VENV) out .ncvm .pytest_cache
