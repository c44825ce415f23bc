# Thin wrapper over the CMake presets. `make demo` and `make test` are the README's quick start:
# both install the Debian packages that are missing first, so either works on a fresh machine.
PRESET ?= release
BUILD := build/$(PRESET)
JOBS ?= $(shell nproc)
GLINT := $(BUILD)/apps/glint/glint

.PHONY: all deps build demo test python format format-check clean

all: build

deps:
	scripts/install-deps.sh

build:
	cmake --preset $(PRESET) >/dev/null
	cmake --build --preset $(PRESET) -j $(JOBS)

demo: deps build
	$(GLINT) render scenes/showcase.yaml -o showcase.png
	@echo "The showcase image is in $(CURDIR)/showcase.png"

test: deps build
	ctest --preset $(PRESET) -j $(JOBS)

# The Python module alone, in $(BUILD)/python: PYTHONPATH=$(BUILD)/python python3 -c "import glint"
python: deps
	cmake --preset $(PRESET) >/dev/null
	cmake --build --preset $(PRESET) -j $(JOBS) --target glint_python
	@echo "glint for Python is in $(CURDIR)/$(BUILD)/python: PYTHONPATH=$(CURDIR)/$(BUILD)/python python3"

format:
	clang-format -i $$(git ls-files '*.h' '*.cpp')

format-check:
	clang-format --dry-run -Werror $$(git ls-files '*.h' '*.cpp')

clean:
	rm -rf build
