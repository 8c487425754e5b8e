!> One simulation of a deck: start position, integration by LSODA or Radau, output rows and
!! summary.
!!
!! Writes `OUTDIR/NAME.dat` (header, then one row per output time) and `OUTDIR/NAME.summary`
!! (`key = value` lines), each through a temporary file renamed when complete, so a failed
!! run leaves no partial file behind.  Both models run through the run loop (module
!! run_loop): kane_run_t (module kane_run) and elastic_run_t (module elastic_solver) step
!! them and check them at every step's end; kane_dat_sink_t and elastic_dat_sink_t here
!! write the rows.
!!
!! The analysis for the driver: simulate_analysis_t (module analysis_base); its
!! preconditions are deck_runs's scene_ready.
module simulate
    use kinds, only: dp
    use status, only: status_t
    use deck, only: deck_t
    use output_io, only: out_files_t
    use sweep_engine, only: sweep_options_t
    use analysis_base, only: analysis_t, WORD_LEN
    implicit none
    private

    !> Figures of one run, also written to the summary file.
    type, public :: run_summary_t
        real(dp) :: cpu_seconds = 0.0_dp
        integer :: steps = 0, rhs_evaluations = 0, jacobian_evaluations = 0, method_switches = 0
        integer :: rows = 0
        real(dp) :: max_abs_theta1 = 0.0_dp, max_abs_theta4 = 0.0_dp, max_q = 0.0_dp
        real(dp) :: max_q_axis = 0.0_dp
        real(dp) :: max_abs_energy_error = 0.0_dp, max_abs_constraint_residual = 0.0_dp
        real(dp) :: min_tension = huge(1.0_dp)
        real(dp) :: tau_reached = 0.0_dp
        !> which of Q and Q_axis, energy_error, constraint_residual the run computed (&output
        !! columns): their maxima are in the summary only then
        logical :: have_sway = .true., have_energy = .true., have_residual = .true.
        !> &integration error_estimate = .true.: largest differences from a rerun at a
        !! tolerance 100 times tighter (angles in rad, Q over b'); -1 when not asked
        real(dp) :: error_estimate_theta = -1.0_dp, error_estimate_q = -1.0_dp
        real(dp) :: error_estimate_rtol = 0.0_dp
        real(dp) :: error_estimate_cpu = 0.0_dp    !! CPU of the rerun (not in cpu_seconds)
        !> model = 'elastic': slack time (tau) and number of slack intervals of BC (1) and
        !! AD (2), and the number of switches between taut and slack (elastic_solver)
        logical :: elastic = .false.
        real(dp) :: slack_time(2) = 0.0_dp
        integer :: slack_intervals(2) = 0
        integer :: cable_switches = 0
        character(len=8) :: method = ''         !! the integrator used: 'lsoda' or 'radau'
    end type run_summary_t

    !> Analysis `simulate` (module analysis_base): OUTDIR/NAME.dat, NAME.summary (and
    !! NAME.slack, elastic cables); its part of the summary line from the run's figures.
    type, extends(analysis_t), public :: simulate_analysis_t
        type(run_summary_t) :: sm               !! the run's figures
    contains
        procedure, nopass :: word => simulate_word
        procedure, nopass :: owned_extensions => simulate_owned
        procedure :: ready => simulate_ready
        procedure :: run => simulate_run
        procedure :: summary => simulate_summary
    end type simulate_analysis_t

    public :: run_simulation

    interface
        !> Run the simulation of a deck and write OUTDIR/NAME.dat and OUTDIR/NAME.summary.
        !! With `files` the files join the run's others there (the caller commits them all
        !! together, or removes them all on failure); without it they are committed at the end
        !! of a successful run and removed on failure.
        module subroutine run_simulation(d, outdir, sm, stat, files)
            type(deck_t), intent(in) :: d           !! the deck
            character(len=*), intent(in) :: outdir  !! output directory
            type(run_summary_t), intent(out) :: sm  !! figures of the run
            type(status_t), intent(out) :: stat     !! ERR_DECK, ERR_NUMERIC, ERR_MODEL or ERR_IO
            type(out_files_t), intent(inout), optional, target :: files  !! the run's files
        end subroutine run_simulation

        !> The preconditions (deck_runs's scene_ready).
        module subroutine simulate_ready(self, d, stat)
            class(simulate_analysis_t), intent(inout) :: self
            type(deck_t), intent(in) :: d           !! the deck
            type(status_t), intent(out) :: stat     !! ERR_DECK, or the start's failure
        end subroutine simulate_ready

        !> The run (run_simulation into the run's files).
        module subroutine simulate_run(self, d, outdir, files, stat, options)
            class(simulate_analysis_t), intent(inout) :: self
            type(deck_t), intent(in) :: d           !! the deck
            character(len=*), intent(in) :: outdir  !! output directory
            type(out_files_t), intent(inout) :: files   !! the run's files
            type(status_t), intent(out) :: stat     !! ERR_DECK, ERR_NUMERIC, ERR_MODEL or ERR_IO
            type(sweep_options_t), intent(in), optional :: options  !! (no sweep)
        end subroutine simulate_run

        !> ' simulate cpu T s, steps N, rhs N, max |dE| E, max |residual| R;'
        module function simulate_summary(self, d) result(s)
            class(simulate_analysis_t), intent(in) :: self
            type(deck_t), intent(in) :: d           !! the deck
            character(len=:), allocatable :: s
        end function simulate_summary
    end interface

contains

    !> The word of &scene analyses.
    function simulate_word() result(w)
        character(len=:), allocatable :: w
        w = 'simulate'
    end function simulate_word

    !> The files it writes: NAME.dat, NAME.summary, NAME.slack.
    subroutine simulate_owned(names)
        character(len=WORD_LEN), allocatable, intent(out) :: names(:)
        names = [character(len=WORD_LEN) :: '.dat', '.summary', '.slack']
    end subroutine simulate_owned

end module simulate
