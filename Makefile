# bifilar: dynamics of the bifilar pendulum (Kane & Tseng 1966)
#   make            build bin/bifilar
#   make test       run all tests (optimised build), last line "N passed, N failed";
#                   ONLY=WORD runs the suites whose name contains WORD (e.g. ONLY=extreme)
#                   and in the others the checks whose label contains it; a WORD that
#                   selects nothing fails (bin/run_tests --list names the suites)
#   make check      run all tests in the checking build (-fcheck=all, FP traps)
#   make mpi        bin/bifilar_mpi, the MPI build (mpirun -np N bin/bifilar_mpi DECK.nml);
#                   installs OpenMPI when run as root, else prints the command and stops
#   make run        run every deck in input/, write output/, draw plots/*.png
#   make report     output/report.md (paper's claims against ours)
#   make bench      integrator, scene, work-precision, elastic-cable, speed, design, record
#                   Monte Carlo and MPI benchmarks
#                   (output/bench_*.dat, plots/work_precision_elastic.png; the speed figures
#                   count instructions with valgrind --tool=callgrind; the MPI figures need
#                   OpenMPI: make mpi)
#   make memcheck   valgrind (leaks, invalid accesses) on a paper deck: bin/bifilar's objects
#                   linked with libc shared (build/memcheck/bifilar)
#   make records    remake the measurements of the identify example decks (bin/make_record:
#                   input/identify_record_swing.dat; prints the periods of
#                   input/identify_periods.nml)
#   make deps       install what a fresh machine lacks (gnuplot)
#   make clean      remove everything built or written

FC = gfortran
MAKEFLAGS += --no-builtin-rules
.SUFFIXES:
.DELETE_ON_ERROR:

CHECK ?= 0
LTO ?= 1
ifeq ($(CHECK),1)
BUILD = build-check
BIN = build-check/bin
# -Og: optimisations that keep debugging (the suites run in 2/3 of -O0's time).  gfortran 12
# takes the descriptor of every local allocatable that is assigned before it is allocated
# (x = expr, reallocated on assignment) for "maybe uninitialized" here: false alarms by the
# dozen.  The optimised build keeps that warning; -fcheck=all checks the same at run time.
FFLAGS = -Og -g -fcheck=all,no-array-temps -ffpe-trap=invalid,zero,overflow -fbacktrace \
         -Wno-maybe-uninitialized
LIBS = -llapack -lblas
DYN_LIBS = $(LIBS)
else ifeq ($(LTO),0)
# LTO=0: an optimised build without link-time optimisation, for iterating on one suite (a
# change recompiles its modules and relinks in seconds, where LTO re-optimises the whole
# program at every link).  Not for measurements: it is slower than bin/.
BUILD = build-nolto
BIN = build-nolto/bin
FFLAGS = -O2 -march=x86-64-v2 -fno-backtrace
LIBS = -llapack -lblas
DYN_LIBS = $(LIBS)
else
BUILD = build
BIN = bin
# -flto inlines across modules (the model's kinematics, forces and solve are one hot path).
# Objects do not depend on the flags: after changing them, make clean.
FFLAGS = -O3 -march=x86-64-v2 -flto=auto -fno-backtrace
# Link statically what Debian ships as archives (LAPACK, BLAS, libgfortran, libquadmath,
# libgomp): the process starts without loading and relocating them.  An archive the compiler
# cannot find falls back to the shared library.  DYN_LIBS keeps libc and libm shared (for
# valgrind's memcheck, which needs malloc in a shared libc).
static_or_shared = $(if $(filter /%,$(shell $(FC) -print-file-name=lib$(1).a)),$(shell \
                   $(FC) -print-file-name=lib$(1).a),-l$(1))
DYN_LIBS := -static-libgcc -Wl,--as-needed $(foreach l,lapack blas gfortran gomp quadmath,$(call \
            static_or_shared,$(l)))
# Where glibc's archive is there too (libc6-dev, which gfortran needs to link anything) and
# every archive above was found (-static takes no shared library), the whole program is
# static: no dynamic loader at all, about 1 ms less CPU a process (README,
# "Speed").  libgfortran calls pthread functions through weak references, which a static
# link leaves at address 0 unless something asks for them (closing a unit then jumps to 0):
# -u asks for each.  glibc's note that a static program cannot dlopen(3), reached through
# libgomp's offloading code, which this program never runs, is left out of the link's
# output (LINK_QUIET); every other message of the linker is shown.
PTHREAD_WEAK = cond_broadcast cond_destroy cond_init cond_wait create getspecific join \
               key_create key_delete mutex_destroy mutex_init mutex_lock mutex_trylock \
               mutex_unlock self setspecific
ifneq ($(and $(filter /%,$(shell $(FC) -print-file-name=libc.a)),$(if $(filter \
       -l%,$(DYN_LIBS)),,yes)),)
LIBS := -static $(foreach f,$(PTHREAD_WEAK),-Wl,-u,pthread_$(f)) $(DYN_LIBS)
LINK_QUIET = 2> $@.ld; s=$$?; grep -v -e 'libgomp.a(target.o): in function' \
             -e "Using 'dlopen' in statically linked" $@.ld >&2; rm -f $@.ld; exit $$s
else
LIBS := $(DYN_LIBS)
endif
endif
FFLAGS += -fopenmp -std=f2008 -Wall -Wextra -Wno-compare-reals -fimplicit-none

# The MPI build (MPI=1, made by `make mpi` and by the tests): the same sources compiled by
# mpif90 into build-mpi (build-check-mpi), with src/parallel/parallel_mpi.f90 as module `parallel`
# in place of the serial parallel.f90; executable $(BIN)/bifilar_mpi.  libgfortran and
# libgomp stay shared there (OpenMPI's Fortran bindings link libgfortran.so), LAPACK and
# BLAS are the same archives as in the serial build (the same numbers, byte for byte).
# The optimised MPI build has no link-time optimisation (LTO=1 compiles it as LTO=0 does, into
# build-mpi, the programs in bin/): its programs are tested for correctness, not timed for
# speed, and each LTO link re-optimises the whole program (minutes of CPU in make test).
MPI ?= 0
ifeq ($(MPI),1)
BUILD := $(BUILD)-mpi
FC = mpif90
ifeq ($(CHECK)$(LTO),01)
FFLAGS := $(subst -O3,-O2,$(filter-out -flto=auto,$(FFLAGS)))
LIBS := $(foreach l,lapack blas,$(call static_or_shared,$(l)))
LINK_QUIET =
endif
PARALLEL_SRC = src/parallel/parallel_mpi.f90
else
PARALLEL_SRC = src/parallel/parallel.f90
endif

# Sources are found by wildcard: the library is every src/*/*.f90 that is not a program
# (src/app/bifilar.f90 and make_record.f90) and not the other build's message passing;
# the test modules are every tests/*.f90 and tests/bench/*.f90 that is not a program.
# One module (or submodule) per file, named as the file; its object is $(BUILD)/NAME.o.
SRC_DIRS := $(patsubst %/,%,$(sort $(dir $(wildcard src/*/*.f90))))
TEST_DIRS := tests tests/bench
PROGRAM_SRC := $(shell grep -l -i -E '^ *program ' $(wildcard src/*/*.f90 tests/*.f90 \
                 tests/bench/*.f90))
LIB_SRC := $(filter-out $(PROGRAM_SRC) src/parallel/parallel.f90 src/parallel/parallel_mpi.f90, \
             $(wildcard src/*/*.f90))
LIB_OBJ = $(patsubst %.f90,$(BUILD)/%.o,$(notdir $(LIB_SRC))) $(BUILD)/parallel.o
TEST_SRC := $(filter-out $(PROGRAM_SRC),$(wildcard tests/*.f90 tests/bench/*.f90))
TEST_OBJ = $(patsubst %.f90,$(BUILD)/%.o,$(notdir $(TEST_SRC)))
vpath %.f90 $(SRC_DIRS) $(TEST_DIRS)

.PHONY: all test check run report bench deps clean memcheck mpi records graph
all: $(BIN)/bifilar

$(BUILD) $(BIN):
	mkdir -p $@

# Dependencies, read from the sources' `use` and `submodule` lines: each object depends on
# the objects of the modules it uses and a submodule on its parent (gfortran writes the
# .mod and .smod files beside them), so make -j builds in the right order and a change
# rebuilds only its users.  build/deps.mk is remade whenever a source changes.  Of
# src/parallel/parallel.f90 and parallel_mpi.f90 (both module `parallel`) each build reads
# its own as parallel.o.
SOURCES = $(LIB_SRC) $(TEST_SRC) $(PARALLEL_SRC)
MODULE_NAMES = $(basename $(notdir $(LIB_SRC) $(TEST_SRC))) parallel
$(BUILD)/deps.mk: $(SOURCES) Makefile | $(BUILD)
	@known=" $(MODULE_NAMES) "; for f in $(SOURCES); do b=$$(basename $$f .f90); b=$${b%_mpi}; \
	  for m in $$(sed -n -e 's/^ *use  *\([a-z0-9_]*\).*/\1/p' \
	                     -e 's/^ *submodule *( *\([a-z0-9_]*\) *).*/\1/p' $$f | sort -u); do \
	    case "$$known" in *" $$m "*) [ "$$m" != "$$b" ] && echo "$(BUILD)/$$b.o: $(BUILD)/$$m.o";; esac; \
	  done; done > $@
include $(BUILD)/deps.mk

$(BUILD)/%.o: %.f90 | $(BUILD)
	$(FC) $(FFLAGS) -J$(BUILD) -c $< -o $@
$(BUILD)/parallel.o: $(PARALLEL_SRC) | $(BUILD)
	$(FC) $(FFLAGS) -J$(BUILD) -c $< -o $@

# Programs: the application's (src/app) link the library; the test runner, the benchmarks
# and probes (tests/, tests/bench/) link the test modules too.
$(BIN)/%: src/app/%.f90 $(LIB_OBJ) | $(BIN)
	$(FC) $(FFLAGS) -J$(BUILD) $< $(LIB_OBJ) $(LIBS) -o $@ $(LINK_QUIET)
$(BIN)/%: tests/%.f90 $(LIB_OBJ) $(TEST_OBJ) | $(BIN)
	$(FC) $(FFLAGS) -J$(BUILD) $< $(LIB_OBJ) $(TEST_OBJ) $(LIBS) -o $@ $(LINK_QUIET)
$(BIN)/%: tests/bench/%.f90 $(LIB_OBJ) $(TEST_OBJ) | $(BIN)
	$(FC) $(FFLAGS) -J$(BUILD) $< $(LIB_OBJ) $(TEST_OBJ) $(LIBS) -o $@ $(LINK_QUIET)
$(BIN)/bifilar_mpi: src/app/bifilar.f90 $(LIB_OBJ) | $(BIN)
	$(FC) $(FFLAGS) -J$(BUILD) $< $(LIB_OBJ) $(LIBS) -o $@ $(LINK_QUIET)
# (the probe uses the library and its task alone: the test modules are not compiled by mpif90)
$(BIN)/sweep_probe_mpi: tests/bench/sweep_probe.f90 $(LIB_OBJ) $(BUILD)/probe_task.o | $(BIN)
	$(FC) $(FFLAGS) -J$(BUILD) $< $(LIB_OBJ) $(BUILD)/probe_task.o $(LIBS) -o $@ $(LINK_QUIET)

# The module graph: one line per module with its floor (tests/module_graph.sh).
graph:
	@tests/module_graph.sh

# make mpi: OpenMPI (installed when missing and run as root), then bin/bifilar_mpi.
mpi:
	@command -v mpif90 >/dev/null 2>&1 && command -v mpirun >/dev/null 2>&1 || { \
	  if [ "$$(id -u)" = 0 ]; then \
	    echo "OpenMPI missing: installing openmpi-bin libopenmpi-dev"; \
	    (apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq \
	      openmpi-bin libopenmpi-dev) >/dev/null || exit 1; \
	  else \
	    echo "OpenMPI is missing; install it with: sudo apt-get install -y openmpi-bin libopenmpi-dev" >&2; \
	    exit 1; \
	  fi; }
	@$(MAKE) --no-print-directory MPI=1 $(BIN)/bifilar_mpi




# The MPI tests (suite sweep) run $(BIN)/bifilar_mpi under mpirun: it is built here when
# OpenMPI is installed; without OpenMPI the suite says so and skips them.
# The programs are built with one job per core (the tests themselves run one at a time).
NPROC := $(shell nproc 2>/dev/null || echo 1)
test:
	@$(MAKE) --no-print-directory -j$(NPROC) $(BIN)/run_tests $(BIN)/bifilar
	@if command -v mpif90 >/dev/null 2>&1; then \
	  $(MAKE) --no-print-directory -j$(NPROC) MPI=1 $(BIN)/bifilar_mpi $(BIN)/sweep_probe_mpi; \
	else echo "note: no OpenMPI (mpif90): the MPI tests are skipped (make mpi installs it)"; fi
	$(BIN)/run_tests $(BIN)/bifilar $(if $(ONLY),"$(ONLY)")

check:
	$(MAKE) CHECK=1 test








bench: $(BIN)/bench_integrator $(BIN)/bench_bifilar $(BIN)/bench_wp $(BIN)/bench_elastic \
       $(BIN)/bench_radau $(BIN)/bench_speed $(BIN)/bench_identify $(BIN)/bifilar \
       $(BIN)/bench_sweep $(BIN)/bench_global_error $(BIN)/bench_platform
	mkdir -p output build/bench
	$(BIN)/bench_integrator output/bench_integrator.dat
	$(BIN)/bench_radau output/bench_radau.dat
	$(BIN)/bench_bifilar output/bench_bifilar.dat
	$(BIN)/bench_wp
	$(BIN)/bench_global_error output/bench_global_error.dat
	$(BIN)/bench_elastic output/bench_elastic.dat
	$(BIN)/bifilar input/work_precision_elastic.nml --out build/bench
	@if command -v gnuplot >/dev/null 2>&1; then gnuplot -c plots/work_precision_elastic.gp \
	  build/bench/work_precision_elastic.wp.dat build/bench/work_precision_elastic.wp_rk4.dat \
	  build/bench/work_precision_elastic.wp_radau.dat plots/work_precision_elastic.png && \
	  echo "drew plots/work_precision_elastic.png"; fi
	@echo "speed: instructions (valgrind --tool=callgrind) and CPU seconds of one unit of work:"
	tests/bench/speed.sh $(BIN) output/bench_speed.dat
	@echo "100 x 100 stability chart (tests/bench/chart_cylinder.nml, OMP_NUM_THREADS=$${OMP_NUM_THREADS:-all cores}):"
	$(BIN)/bifilar tests/bench/chart_cylinder.nml --out build/bench 2>/dev/null
	@echo "100 x 100 stability chart of a trifilar platform (tests/bench/chart_platform.nml):"
	$(BIN)/bifilar tests/bench/chart_platform.nml --out build/bench 2>/dev/null
	@echo "60 x 6 rig design (input/box_design.nml, OMP_NUM_THREADS=$${OMP_NUM_THREADS:-all cores}: under 20 s on 2 cores):"
	$(BIN)/bifilar input/box_design.nml --out build/bench 2>/dev/null
	@echo "a record fit with 200 Monte Carlo refits (input/more/identify_record_mc.nml, OMP_NUM_THREADS=$${OMP_NUM_THREADS:-all cores}: the refits' wall time, under 1 s on 2 cores):"
	$(BIN)/bifilar input/more/identify_record_mc.nml --out build/bench 2>/dev/null
	@if command -v mpif90 >/dev/null 2>&1; then \
	  $(MAKE) --no-print-directory MPI=1 $(BIN)/bifilar_mpi $(BIN)/sweep_probe_mpi; fi
	@echo "MPI: strong scaling of the 60 x 45 chart and of identify's Monte Carlo, the cost of the chart's points, the model of 1000 x 1000:"
	tests/bench/mpi_scaling.sh $(BIN) output/bench_mpi.dat
	@echo "tensor: the 9-hang example without Monte Carlo (aim: under 1 s) and its 2000 Monte Carlo samples on 2 threads (aim: under 30 s):"
	tests/bench/tensor_speed.sh $(BIN) output/bench_tensor.dat

# memcheck needs a shared libc (its malloc): bin/bifilar's objects, linked with DYN_LIBS.
memcheck: src/app/bifilar.f90 $(LIB_OBJ)
	mkdir -p build/memcheck
	$(FC) $(FFLAGS) -J$(BUILD) $< $(LIB_OBJ) $(DYN_LIBS) -o build/memcheck/bifilar
	valgrind --leak-check=full --error-exitcode=1 build/memcheck/bifilar \
	  input/cylinder_l195.nml --out build/memcheck

# The measurements of the identify example decks, made by the program itself from the true
# rigs in input/truth/ (committed: make run needs them; remaking them gives the same files).
records: $(BIN)/make_record
	$(BIN)/make_record record input/truth/identify_record_truth.nml 30 100 0.002 10 rate \
	  input/identify_record_swing.dat
	@echo "periods of input/identify_periods.nml (&measurement):"
	$(BIN)/make_record periods input/truth/identify_periods_truth.nml 1e-4 7 10 30 60
	$(BIN)/make_record trials input/truth/identify_trials_truth.nml input/identify_trials.csv \
	  11 0.05 0.002 3 2 10 10 0.8 1.2 1.6 2.0
	@# the periods of the tensor example's hangs (input/tensor_example.nml)
	$(BIN)/make_record hangs input/truth/tensor_example_truth.nml 0 1 input/tensor_example_hangs.csv
	@# the periods of the tensor-on-a-platform example's hangs (input/tensor_platform.nml)
	$(BIN)/make_record hangs input/truth/tensor_platform_truth.nml 0 1 input/tensor_platform_hangs.csv

DECKS = $(wildcard input/*.nml)
run: deps $(BIN)/bifilar
	$(BIN)/bifilar $(DECKS)
	$(BIN)/bifilar --report output
	@$(MAKE) --no-print-directory plots

report: $(BIN)/bifilar
	mkdir -p output
	$(BIN)/bifilar $(patsubst %,input/%.nml,cylinder_l180 cylinder_l195 triangle_plate cylinder_torsion)
	$(BIN)/bifilar --report output

.PHONY: certificate-check
certificate-check:
	tests/tools/certificate_check.sh

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
	rm -rf build build-check build-nolto build-nolto-mpi build-mpi build-check-mpi bin output/*.dat output/*.summary \
	  output/*.md output/*.design output/*.identify output/*.certificate.html output/*.calibration output/*.tmp.* output/*.partial plots/*.png
