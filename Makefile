# bifilar: dynamics of the bifilar pendulum (Kane & Tseng 1966)
#   make            build bin/bifilar
#   make test       run all tests (optimised build), last line "N passed, N failed";
#                   ONLY=WORD runs the suites whose name contains WORD (e.g. ONLY=extreme)
#   make check      run all tests in the checking build (-fcheck=all, FP traps)
#   make run        run every deck in input/, write output/, draw plots/*.png
#   make report     output/report.md (paper's claims against ours)
#   make bench      integrator, scene and work-precision benchmarks (output/bench_*.dat)
#   make memcheck   valgrind (leaks, invalid accesses) on bin/bifilar with a paper deck
#   make deps       install what a fresh machine lacks (gnuplot)
#   make clean      remove everything built or written

FC = gfortran
MAKEFLAGS += --no-builtin-rules
.SUFFIXES:
.DELETE_ON_ERROR:

CHECK ?= 0
ifeq ($(CHECK),1)
BUILD = build-check
BIN = build-check/bin
FFLAGS = -O0 -g -fcheck=all,no-array-temps -ffpe-trap=invalid,zero,overflow -fbacktrace
else
BUILD = build
BIN = bin
FFLAGS = -O2 -march=x86-64-v2 -fno-backtrace
endif
FFLAGS += -fopenmp -std=f2008 -Wall -Wextra -Wno-compare-reals -fimplicit-none
LIBS = -llapack -lblas

# Library modules in dependency order (each only uses modules listed before it).
LIB_MODULES = kinds status random lapack_wrap ode_system lsoda geometry kinematics gen_forces bifilar_model \
              elastic_model elastic_solver deck output_io simulate floquet paper_claims stability work_precision period_inversion
LIB_OBJ = $(patsubst %,$(BUILD)/%.o,$(LIB_MODULES))
TEST_MODULES = testing test_lsoda test_model test_deck test_floquet test_extreme test_work_precision test_elastic test_elastic_jac test_period
TEST_OBJ = $(patsubst %,$(BUILD)/%.o,$(TEST_MODULES))

.PHONY: all test check run report bench deps clean memcheck
all: $(BIN)/bifilar

$(BUILD) $(BIN):
	mkdir -p $@

# Every object depends on all objects listed before it (simple, correct ordering).
define chain
$(BUILD)/$(word $(1),$(2)).o: $(patsubst %,$(BUILD)/%.o,$(wordlist 1,$(shell expr $(1) - 1),$(2)))
endef
ALL_MODULES = $(LIB_MODULES) $(TEST_MODULES)
$(foreach i,$(shell seq 2 $(words $(ALL_MODULES))),$(eval $(call chain,$(i),$(ALL_MODULES))))

$(BUILD)/%.o: src/%.f90 | $(BUILD)
	$(FC) $(FFLAGS) -J$(BUILD) -c $< -o $@
$(BUILD)/%.o: tests/%.f90 | $(BUILD)
	$(FC) $(FFLAGS) -J$(BUILD) -c $< -o $@

$(BIN)/bifilar: src/bifilar.f90 $(LIB_OBJ) | $(BIN)
	$(FC) $(FFLAGS) -J$(BUILD) $< $(LIB_OBJ) $(LIBS) -o $@

$(BIN)/run_tests: tests/run_tests.f90 $(LIB_OBJ) $(TEST_OBJ) | $(BIN)
	$(FC) $(FFLAGS) -J$(BUILD) $< $(LIB_OBJ) $(TEST_OBJ) $(LIBS) -o $@

$(BIN)/bench_integrator: tests/bench_integrator.f90 $(LIB_OBJ) $(BUILD)/test_lsoda.o | $(BIN)
	$(FC) $(FFLAGS) -J$(BUILD) $< $(LIB_OBJ) $(BUILD)/test_lsoda.o $(BUILD)/testing.o $(LIBS) -o $@

test: $(BIN)/run_tests $(BIN)/bifilar
	$(BIN)/run_tests $(BIN)/bifilar $(ONLY)

check:
	$(MAKE) CHECK=1 test

$(BIN)/bench_bifilar: tests/bench_bifilar.f90 $(LIB_OBJ) | $(BIN)
	$(FC) $(FFLAGS) -J$(BUILD) $< $(LIB_OBJ) $(LIBS) -o $@

$(BIN)/bench_elastic: tests/bench_elastic.f90 $(LIB_OBJ) | $(BIN)
	$(FC) $(FFLAGS) -J$(BUILD) $< $(LIB_OBJ) $(LIBS) -o $@

$(BIN)/bench_wp: tests/bench_wp.f90 $(LIB_OBJ) | $(BIN)
	$(FC) $(FFLAGS) -J$(BUILD) $< $(LIB_OBJ) $(LIBS) -o $@

bench: $(BIN)/bench_integrator $(BIN)/bench_bifilar $(BIN)/bench_wp $(BIN)/bench_elastic \
       $(BIN)/bifilar
	mkdir -p output build/bench
	$(BIN)/bench_integrator output/bench_integrator.dat
	$(BIN)/bench_bifilar output/bench_bifilar.dat
	$(BIN)/bench_wp
	$(BIN)/bench_elastic output/bench_elastic.dat
	@echo "100 x 100 stability chart (tests/bench/chart_cylinder.nml, OMP_NUM_THREADS=$${OMP_NUM_THREADS:-all cores}):"
	$(BIN)/bifilar tests/bench/chart_cylinder.nml --out build/bench 2>/dev/null

memcheck: $(BIN)/bifilar
	mkdir -p build/memcheck
	valgrind --leak-check=full --error-exitcode=1 $(BIN)/bifilar input/cylinder_l195.nml \
	  --out build/memcheck

DECKS = $(wildcard input/*.nml)
run: deps $(BIN)/bifilar
	mkdir -p output
	@set -e; for d in $(DECKS); do echo "bifilar $$d"; $(BIN)/bifilar $$d; done
	$(BIN)/bifilar --report output
	@$(MAKE) --no-print-directory plots

report: $(BIN)/bifilar
	mkdir -p output
	@set -e; for d in cylinder_l180 cylinder_l195 triangle_plate cylinder_torsion; do \
	  $(BIN)/bifilar input/$$d.nml; done
	$(BIN)/bifilar --report output

.PHONY: plots
plots:
	@set -e; for s in plots/*.gp; do gnuplot -c $$s || exit 1; done

deps:
	@command -v gnuplot >/dev/null 2>&1 || { \
	  if [ "$$(id -u)" = 0 ]; then \
	    echo "gnuplot missing: installing gnuplot-nox"; \
	    (apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq gnuplot-nox) >/dev/null; \
	  else \
	    echo "gnuplot is missing; install it with: sudo apt-get install -y gnuplot-nox" >&2; exit 1; \
	  fi; }

clean:
	rm -rf build build-check bin output/*.dat output/*.summary output/*.md output/*.tmp plots/*.png
