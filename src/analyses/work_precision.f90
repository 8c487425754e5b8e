!> Error against run time (analysis `work_precision`): the scene of a deck solved by LSODA
!! at rtol = 1e-3 ... 1e-12 (atol scaled with it) and by fixed-step classical Runge-Kutta 4
!! (the method a hand-written program of 1966 would use), each against a reference solution
!! at the deck's output times.
!!
!! The reference is LSODA at rtol = 1e-13, confirmed by an independent method: fixed-step
!! RK4 at steps h and h/2 combined by Richardson extrapolation, (16 y(h/2) - y(h))/15.
!! Their largest difference is reported (`reference_agreement_*`); a test holds it small.
!! The elastic model (model = 'elastic') adds a third curve, Radau IIA (its default
!! integrator, in the generalized coordinates of elastic_gen), written to NAME.wp_radau.dat;
!! its reference is Radau at rtol = 1e-13, confirmed by LSODA at rtol = 1e-13 in the
!! maximal coordinates (an independent integrator in independent coordinates; agreement
!! in `ref_second_*`) and by RK4 + Richardson where that stays below 4096 steps per
!! output interval.
!!
!! Errors at the output times: error_theta = the largest angle error (theta1, theta4,
!! theta5 and the direction of the cable BC, see kane_run's angle_difference), error_Q =
!! the largest |Q error| (over b'), max_abs_energy_error = the largest |E - E(0)| (over
!! m g b').  CPU seconds are per solve, from repeated solves until at least 0.05 s.
!! Writes OUTDIR/NAME.wp.dat and OUTDIR/NAME.wp_rk4.dat.
!!
!! The analysis for the driver: work_precision_analysis_t (module analysis_base); its
!! preconditions are deck_runs's scene_ready.
module work_precision
    use kinds, only: dp
    use status, only: status_t
    use geometry, only: pendulum_t
    use bifilar_model, only: NSTATE
    use ode_system, only: ode_system_t
    use deck, only: deck_t
    use output_io, only: out_files_t
    use sweep_engine, only: sweep_options_t
    use analysis_base, only: analysis_t, WORD_LEN
    implicit none
    private

    integer, parameter, public :: WP_NRTOL = 10          !! rtol = 1e-3 ... 1e-12

    integer, parameter, public :: WP_NRK4 = 7            !! h = dtau_out / 2**(0..6)

    real(dp), parameter, public :: WP_REF_RTOL = 1.0e-13_dp

    !> RK4 substeps per output interval of the reference check (h and h/2)
    integer, parameter, public :: WP_REF_SUBSTEPS = 64

    !> One point of a work-precision curve.
    type, public :: wp_point_t
        real(dp) :: rtol = 0.0_dp               !! LSODA: rtol; RK4: 0
        real(dp) :: h = 0.0_dp                  !! RK4: step; LSODA: 0
        real(dp) :: cpu_seconds = 0.0_dp        !! per solve
        integer :: steps = 0, rhs_evaluations = 0
        real(dp) :: error_theta = 0.0_dp, error_q = 0.0_dp, max_abs_energy_error = 0.0_dp
        logical :: ok = .false.                 !! the solve finished
    end type wp_point_t

    type, public :: wp_result_t
        type(wp_point_t) :: lsoda(WP_NRTOL)
        type(wp_point_t) :: rk4(WP_NRK4)
        type(wp_point_t) :: radau(WP_NRTOL)        !! model = 'elastic' only
        real(dp) :: ref_agreement_theta = 0.0_dp   !! the reference against RK4 + Richardson
        real(dp) :: ref_agreement_q = 0.0_dp
        !> model = 'elastic': the reference (Radau 1e-13) against LSODA 1e-13; -1 otherwise
        real(dp) :: ref_second_theta = -1.0_dp, ref_second_q = -1.0_dp
        real(dp) :: ref_h = 0.0_dp                 !! RK4 step of the confirmation (coarser)
        integer :: nout = 0
    end type wp_result_t

    !> Analysis `work_precision` (module analysis_base): OUTDIR/NAME.wp.dat, NAME.wp_rk4.dat
    !! (and NAME.wp_radau.dat, elastic cables); its part of the summary line from the curves.
    type, extends(analysis_t), public :: work_precision_analysis_t
        type(wp_result_t) :: res                !! the curves
    contains
        procedure, nopass :: word => work_precision_word
        procedure, nopass :: owned_extensions => work_precision_owned
        procedure :: ready => work_precision_ready
        procedure :: run => work_precision_run
        procedure :: summary => work_precision_summary
    end type work_precision_analysis_t

    public :: run_work_precision, solve_lsoda, solve_rk4, solve_rk4_sys
    public :: trajectory_errors

    interface
        !> The analysis: reference, its confirmation, both curves, the two files.  With `files`
        !! the files join the run's others (see run_simulation); without it they are committed
        !! at the end.
        module subroutine run_work_precision(d, outdir, res, stat, quiet, files)
            type(deck_t), intent(in) :: d           !! the deck
            character(len=*), intent(in) :: outdir  !! output directory
            type(wp_result_t), intent(out) :: res   !! the curves
            type(status_t), intent(out) :: stat     !! ERR_DECK, ERR_NUMERIC, ERR_MODEL, ERR_IO
            logical, intent(in), optional :: quiet  !! do not print the agreement line
            type(out_files_t), intent(inout), optional, target :: files  !! the run's files
        end subroutine run_work_precision

        !> LSODA from y0 at times(0) to every later time.
        module subroutine solve_lsoda(p, y0, times, rtol, atol, ys, steps, nfe, stat)
            type(pendulum_t), intent(in) :: p       !! scaled parameters
            real(dp), intent(in) :: y0(NSTATE)      !! state at times(0)
            real(dp), intent(in) :: times(0:)       !! output times, increasing
            real(dp), intent(in) :: rtol, atol      !! tolerances
            real(dp), intent(out) :: ys(:, 0:)      !! (NSTATE, 0:n) states at the times
            integer, intent(out) :: steps, nfe      !! integrator counters
            type(status_t), intent(out) :: stat     !! the integrator's failure
        end subroutine solve_lsoda

        !> Fixed-step classical Runge-Kutta 4 with `m` equal steps per output interval.
        module subroutine solve_rk4(p, y0, times, m, ys, steps, nfe, stat)
            type(pendulum_t), intent(in) :: p       !! scaled parameters
            real(dp), intent(in) :: y0(NSTATE)      !! state at times(0)
            real(dp), intent(in) :: times(0:)       !! output times, increasing
            integer, intent(in) :: m                !! steps per output interval
            real(dp), intent(out) :: ys(:, 0:)      !! (NSTATE, 0:n) states at the times
            integer, intent(out) :: steps, nfe      !! steps and right-hand-side evaluations
            type(status_t), intent(out) :: stat     !! a right-hand-side failure or non-finite state
        end subroutine solve_rk4

        !> Fixed-step RK4 on any system (the paper's or the elastic model).
        module subroutine solve_rk4_sys(sys, y0, times, m, ys, steps, nfe, stat)
            class(ode_system_t), intent(inout) :: sys   !! the equations of motion
            real(dp), intent(in) :: y0(:)           !! state at times(0)
            real(dp), intent(in) :: times(0:)       !! output times, increasing
            integer, intent(in) :: m                !! steps per output interval
            real(dp), intent(out) :: ys(:, 0:)      !! (n, 0:nout) states at the times
            integer, intent(out) :: steps, nfe      !! steps and right-hand-side evaluations
            type(status_t), intent(out) :: stat     !! a right-hand-side failure or non-finite state
        end subroutine solve_rk4_sys

        !> Errors of a trajectory against the reference at the output times, and its energy
        !! error against its own start.
        module subroutine trajectory_errors(p, ys, yref, err_theta, err_q, err_energy)
            type(pendulum_t), intent(in) :: p       !! scaled parameters
            real(dp), intent(in) :: ys(:, 0:)       !! trajectory at the output times
            real(dp), intent(in) :: yref(:, 0:)     !! reference at the same times
            real(dp), intent(out) :: err_theta, err_q, err_energy
        end subroutine trajectory_errors

        !> The preconditions (deck_runs's scene_ready).
        module subroutine work_precision_ready(self, d, stat)
            class(work_precision_analysis_t), intent(inout) :: self
            type(deck_t), intent(in) :: d           !! the deck
            type(status_t), intent(out) :: stat     !! ERR_DECK, or the start's failure
        end subroutine work_precision_ready

        !> The run (run_work_precision, quiet, into the run's files).
        module subroutine work_precision_run(self, d, outdir, files, stat, options)
            class(work_precision_analysis_t), intent(inout) :: self
            type(deck_t), intent(in) :: d           !! the deck
            character(len=*), intent(in) :: outdir  !! output directory
            type(out_files_t), intent(inout) :: files   !! the run's files
            type(status_t), intent(out) :: stat     !! ERR_DECK, ERR_NUMERIC, ERR_MODEL, ERR_IO
            type(sweep_options_t), intent(in), optional :: options  !! (no sweep)
        end subroutine work_precision_run

        !> ' work_precision N LSODA, [N Radau,] N RK4 points, reference confirmed to E rad;'
        module function work_precision_summary(self, d) result(s)
            class(work_precision_analysis_t), intent(in) :: self
            type(deck_t), intent(in) :: d           !! the deck (&scene model)
            character(len=:), allocatable :: s
        end function work_precision_summary
    end interface

contains

    !> The word of &scene analyses.
    function work_precision_word() result(w)
        character(len=:), allocatable :: w
        w = 'work_precision'
    end function work_precision_word

    !> The files it writes: NAME.wp.dat, NAME.wp_rk4.dat, NAME.wp_radau.dat.
    subroutine work_precision_owned(names)
        character(len=WORD_LEN), allocatable, intent(out) :: names(:)
        names = [character(len=WORD_LEN) :: '.wp.dat', '.wp_rk4.dat', '.wp_radau.dat']
    end subroutine work_precision_owned

end module work_precision
