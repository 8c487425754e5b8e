!> The stability analyses of a deck: `floquet` (one amplitude) and `chart` (a grid of two
!! deck parameters), Kane & Tseng (1966) eqs. (45)-(51).
!!
!! Writes OUTDIR/NAME.floquet (key = value lines and the multiplier table) and
!! OUTDIR/NAME.chart.dat (x, y, max_modulus, period), each through a temporary file.
!! The chart's points are a sweep (module sweep_engine): spread over the OpenMP threads
!! (OMP_NUM_THREADS is honoured) and, in bin/bifilar_mpi, over the MPI ranks, checkpointed
!! to OUTDIR/NAME.chart.partial as they complete, with one line of progress on standard
!! error when that is a terminal (module progress); floquet_point is the point shared with
!! the rig design (module design).
!!
!! The analyses for the driver (module analysis_base): floquet_analysis_t and
!! chart_analysis_t; both need an undamped torsion (deck_runs's undamped_ready), the chart
!! runs before the analyses without a sweep of their own (runs_first).
module stability
    use kinds, only: dp
    use status, only: status_t
    use geometry, only: pendulum_t
    use deck, only: deck_t
    use floquet, only: floquet_result_t
    use output_io, only: out_files_t
    use sweep_engine, only: sweep_task_t, sweep_options_t, sweep_report_t
    use analysis_base, only: analysis_t, WORD_LEN
    implicit none
    private

    !> The points of a chart as a sweep: point k = (i, j) of the grid, x index i fastest
    !! (k = (j - 1) nx + i); its values are max_modulus and period.
    type, extends(sweep_task_t), public :: chart_task_t
        type(pendulum_t) :: p0                  !! the deck's scene
        character(len=16) :: x = '', y = ''     !! the swept variables
        real(dp), allocatable :: xs(:), ys(:)   !! their grids (chart units)
        real(dp) :: amplitude = 0.0_dp          !! &floquet amplitude (degrees)
        real(dp) :: rtol = 0.0_dp               !! &floquet rtol
        integer :: segments = 1                 !! &floquet segments
        integer :: method = 1                   !! the integrator (module integrators)
        !> the monodromy's way (module integrators: SENS_FORWARD, SENS_DIFFERENCES)
        integer :: sensitivities = 1
    contains
        procedure :: compute => chart_point
        procedure :: accepts => chart_accepts
    end type chart_task_t

    !> Analysis `floquet` (module analysis_base): OUTDIR/NAME.floquet; its part of the
    !! summary line: the period, the largest modulus, stable or not.
    type, extends(analysis_t), public :: floquet_analysis_t
        type(floquet_result_t) :: res           !! what the analysis found
    contains
        procedure, nopass :: word => floquet_word
        procedure, nopass :: owned_extensions => floquet_owned
        procedure :: ready => floquet_analysis_ready
        procedure :: run => floquet_analysis_run
        procedure :: summary => floquet_summary
    end type floquet_analysis_t

    !> Analysis `chart` (module analysis_base): OUTDIR/NAME.chart.dat from the sweep
    !! 'chart' (checkpoint OUTDIR/NAME.chart.partial), run before the others; its part of
    !! the summary line: the points, the stable ones, the time, the ranks, the failed points,
    !! what --resume took.
    type, extends(analysis_t), public :: chart_analysis_t
        integer :: nstable = 0                  !! stable points
        integer :: nfailed = 0                  !! points whose analysis failed
        real(dp) :: wall_seconds = 0.0_dp       !! the sweep's time
        type(sweep_report_t) :: rep             !! how the sweep went
    contains
        procedure, nopass :: word => chart_word
        procedure, nopass :: owned_extensions => chart_owned
        procedure, nopass :: sweeps => chart_sweeps
        procedure, nopass :: runs_first => chart_first
        procedure :: ready => chart_analysis_ready
        procedure :: run => chart_analysis_run
        procedure :: summary => chart_summary
        procedure :: sweep_task => chart_sweep_task
    end type chart_analysis_t

    public :: run_floquet, run_chart, set_chart_variable, floquet_ready, chart_task

    interface
        !> Floquet analysis of a deck at &floquet amplitude: OUTDIR/NAME.floquet.  With `files`
        !! the file joins the run's others (see run_simulation); without it it is committed at
        !! once.
        module subroutine run_floquet(d, outdir, res, stat, files)
            type(deck_t), intent(in) :: d           !! the deck (a torsion scene)
            character(len=*), intent(in) :: outdir  !! output directory
            type(floquet_result_t), intent(out) :: res
            type(status_t), intent(out) :: stat     !! ERR_DECK (not a torsion scene), ERR_NUMERIC
            type(out_files_t), intent(inout), optional, target :: files  !! the run's files
        end subroutine run_floquet

        !> Stability chart over the grid of &chart: OUTDIR/NAME.chart.dat with one row per point,
        !! `x y max_modulus period` (CHART_INVALID where no analysis is possible, CHART_FAILED
        !! where it failed), a blank line after each x (gnuplot grid format).  The points are a
        !! sweep over threads and ranks, checkpointed to OUTDIR/NAME.chart.partial (see module
        !! sweep_engine; `options`: --resume and the checkpoint interval).  With `files` the file
        !! joins the run's others (see run_simulation); without it it is committed at once.
        module subroutine run_chart(d, outdir, nstable, wall_seconds, stat, files, nfailed, options, &
                             report)
            type(deck_t), intent(in) :: d           !! the deck
            character(len=*), intent(in) :: outdir  !! output directory
            integer, intent(out) :: nstable         !! number of stable points
            real(dp), intent(out) :: wall_seconds   !! elapsed time of the sweep
            type(status_t), intent(out) :: stat
            type(out_files_t), intent(inout), optional, target :: files  !! the run's files
            integer, intent(out), optional :: nfailed   !! number of points whose analysis failed
            type(sweep_options_t), intent(in), optional :: options  !! resume, checkpoint interval
            type(sweep_report_t), intent(out), optional :: report   !! ranks, resumed points, ...
        end subroutine run_chart

        !> Set one chart variable (deck units: l and b over b', amplitude in degrees, r over b',
        !! lambda in radians, inertia_ratio = I3/I1) in p, or the amplitude.
        module pure subroutine set_chart_variable(name, value, p, amp_deg)
            character(len=*), intent(in) :: name    !! l, b, amplitude, r, lambda, inertia_ratio
            real(dp), intent(in) :: value
            type(pendulum_t), intent(inout) :: p
            real(dp), intent(inout) :: amp_deg      !! torsion amplitude (degrees)
        end subroutine set_chart_variable

        !> The preconditions of analyses = 'floquet', checked before any computing: the cables
        !! can reach and pure torsion is an exact motion of the scene (ERR_DECK otherwise).
        module subroutine floquet_ready(d, stat)
            type(deck_t), intent(in) :: d           !! the deck
            type(status_t), intent(out) :: stat     !! ERR_DECK
        end subroutine floquet_ready

        !> The chart of a deck as a sweep (also built by the other ranks of an MPI run from the
        !! same deck): the scene, the swept variables and their grids.
        module subroutine chart_task(d, task, stat)
            type(deck_t), intent(in) :: d           !! the deck
            type(chart_task_t), intent(out) :: task
            type(status_t), intent(out) :: stat     !! ERR_DECK when the scene cannot be made
        end subroutine chart_task

        !> Chart point k: values = [max_modulus, period] (sentinels, see floquet_point).  Never
        !! fails itself.
        module subroutine chart_point(self, i, values, stat)
            class(chart_task_t), intent(in) :: self
            integer, intent(in) :: i                !! 1 .. nx*ny, x index fastest
            real(dp), intent(out) :: values(:)      !! max_modulus, period
            type(status_t), intent(out) :: stat     !! always OK
        end subroutine chart_point

        !> Whether values could be chart point i's (read back from a checkpoint): a modulus
        !! >= 0 with a period > 0, both finite, or a sentinel in both (floquet_point).
        module logical function chart_accepts(self, i, values)
            class(chart_task_t), intent(in) :: self
            integer, intent(in) :: i                !! 1 .. nx*ny
            real(dp), intent(in) :: values(:)       !! max_modulus, period
        end function chart_accepts

        !> The preconditions of floquet: floquet_ready, and no &damping (undamped_ready).
        module subroutine floquet_analysis_ready(self, d, stat)
            class(floquet_analysis_t), intent(inout) :: self
            type(deck_t), intent(in) :: d           !! the deck
            type(status_t), intent(out) :: stat     !! ERR_DECK
        end subroutine floquet_analysis_ready

        !> The run (run_floquet into the run's files).
        module subroutine floquet_analysis_run(self, d, outdir, files, stat, options)
            class(floquet_analysis_t), intent(inout) :: self
            type(deck_t), intent(in) :: d           !! the deck
            character(len=*), intent(in) :: outdir  !! output directory
            type(out_files_t), intent(inout) :: files   !! the run's files
            type(status_t), intent(out) :: stat     !! ERR_DECK, ERR_NUMERIC
            type(sweep_options_t), intent(in), optional :: options  !! (no sweep)
        end subroutine floquet_analysis_run

        !> ' floquet period P, max modulus M, stable yes|no;'
        module function floquet_summary(self, d) result(s)
            class(floquet_analysis_t), intent(in) :: self
            type(deck_t), intent(in) :: d           !! the deck
            character(len=:), allocatable :: s
        end function floquet_summary

        !> The preconditions of chart: the deck's own scene has a reachable geometry (each
        !! point of the grid is checked when it is computed), and no &damping
        !! (undamped_ready).
        module subroutine chart_analysis_ready(self, d, stat)
            class(chart_analysis_t), intent(inout) :: self
            type(deck_t), intent(in) :: d           !! the deck
            type(status_t), intent(out) :: stat     !! ERR_DECK
        end subroutine chart_analysis_ready

        !> The run (run_chart into the run's files).
        module subroutine chart_analysis_run(self, d, outdir, files, stat, options)
            class(chart_analysis_t), intent(inout) :: self
            type(deck_t), intent(in) :: d           !! the deck
            character(len=*), intent(in) :: outdir  !! output directory
            type(out_files_t), intent(inout) :: files   !! the run's files
            type(status_t), intent(out) :: stat
            type(sweep_options_t), intent(in), optional :: options  !! --resume, the interval
        end subroutine chart_analysis_run

        !> ' chart N points, N stable, T s[ on N ranks][, N failed (-2 in the file)][resume];'
        module function chart_summary(self, d) result(s)
            class(chart_analysis_t), intent(in) :: self
            type(deck_t), intent(in) :: d           !! the deck (&chart nx, ny)
            character(len=:), allocatable :: s
        end function chart_summary

        !> The task of sweep 'chart' on the other ranks of an MPI run (chart_task).
        module subroutine chart_sweep_task(self, sweep, d, payload, task, stat)
            class(chart_analysis_t), intent(in) :: self
            character(len=*), intent(in) :: sweep   !! 'chart'
            type(deck_t), intent(in) :: d           !! the deck
            real(dp), intent(in) :: payload(:)      !! the sweep's payload (none)
            class(sweep_task_t), allocatable, intent(out) :: task
            type(status_t), intent(out) :: stat     !! ERR_DECK when the scene cannot be made
        end subroutine chart_sweep_task
    end interface

contains

    !> The word of &scene analyses.
    function floquet_word() result(w)
        character(len=:), allocatable :: w
        w = 'floquet'
    end function floquet_word

    !> The file it writes: NAME.floquet.
    subroutine floquet_owned(names)
        character(len=WORD_LEN), allocatable, intent(out) :: names(:)
        names = [character(len=WORD_LEN) :: '.floquet']
    end subroutine floquet_owned

    !> The word of &scene analyses.
    function chart_word() result(w)
        character(len=:), allocatable :: w
        w = 'chart'
    end function chart_word

    !> The file it writes: NAME.chart.dat.
    subroutine chart_owned(names)
        character(len=WORD_LEN), allocatable, intent(out) :: names(:)
        names = [character(len=WORD_LEN) :: '.chart.dat']
    end subroutine chart_owned

    !> Its sweep: 'chart' (checkpoint NAME.chart.partial).
    subroutine chart_sweeps(names)
        character(len=WORD_LEN), allocatable, intent(out) :: names(:)
        names = [character(len=WORD_LEN) :: 'chart']
    end subroutine chart_sweeps

    !> The chart runs before the analyses without it (no file of the deck staged meanwhile).
    logical function chart_first()
        chart_first = .true.
    end function chart_first

end module stability
