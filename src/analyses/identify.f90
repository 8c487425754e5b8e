!> The moment of inertia I1 from what was measured (analysis identify): measured periods
!! or a recorded swing, with damping and an uncertainty budget.
!!
!! * Periods (&measurement periods, amplitudes): module period_inversion.  I1 by weighted
!!   least squares from the exact period of pure torsion (eqs. (45)-(49)) on a symmetric
!!   rig, or from the full model's period on any other (simulated_period_s); first-order
!!   budget by central differences of the whole inversion; Monte Carlo by re-inverting with
!!   every input drawn from its normal distribution.  Without u_period, two periods or more
!!   give it as their scatter about the model (s^2 = sum of squares over n - 1), and the
!!   inversion, budget and Monte Carlo use that.
!! * A record (&measurement record): time (s) and theta4 (rad, quantity = 'angle') or
!!   W = omega . n3 (rad/s, quantity = 'rate'), optionally each sample's standard
!!   uncertainty.  The full nonlinear model (unequal cables, offset mass centre, tilting and
!!   sway as they come, the damping torque of &damping) is started from the deck's &start
!!   at t = t0 (the record's time of release, 0 unless estimated; a sample before t0 sees
!!   the body held at the start) and run in memory through the run loop (module run_loop)
!!   to the record's last sample; its value at the sample times is compared with the
!!   record.  The parameters of &measurement estimate (I1 and any of c_v, c_q, amplitude,
!!   t0) minimise sum ((model - measured)/u_i)^2 (u_i = 1 without column 3) by
!!   the estimator (module estimator: Levenberg-Marquardt), with forward differences of the model.
!!   An oscillation's phase makes the misfit many-valued in I1 over a long record, so the
!!   fit runs first on about two periods of the record (its mean period from the zero
!!   crossings), then on windows twice as long, each from the last estimate, up to the
!!   whole record.
!! * First-order uncertainty (GUM, JCGM 100:2008): the fit's covariance
!!   C = s^2 (J^T W J)^-1, J by central differences at the estimate, s = 1 when the record
!!   gives each sample's uncertainty (column 3: 'stated'), else s^2 = the residuals' sum of
!!   squares over (samples - parameters) ('residuals'); plus each stated input uncertainty
!!   (mass, l, l_prime, b, b_prime, g, and the start amplitude when it is held) times the
!!   estimate's sensitivity to that input, by the implicit-function form
!!   dp/dx = -(J^T W J)^-1 J^T W dr/dx (to first order the refit's change; dr/dx by central
!!   differences, two model runs per input).  u_P^2 = C_PP + sum_x (dP/dx u_x)^2.  The
!!   period's uncertainty u_period is not an input of a record fit (the record's noise is
!!   in the residuals or column 3).
!! * Monte Carlo (GUM Supplement 1, JCGM 101:2008), monte_carlo = N samples: sample k draws,
!!   from stream k of the seed (module random), every input from N(x, u_x^2) (the order
!!   mass, l, l_prime, b, b_prime, g, amplitude) and then every measured value from
!!   N(v_i, s_i^2) (s_i the stated u_i or s), and refits from the estimate: Gauss-Newton
!!   with the estimate's Jacobian (each step one model run) until the step is below 1e-3 of
!!   each parameter's first-order u, else Levenberg-Marquardt.  u_I1_monte_carlo is the
!!   samples' standard deviation.  A sample depends only on (seed, k): any order, thread or
!!   rank gives the same numbers.  The samples (of periods too) are a sweep (module
!!   monte_carlo) over the OpenMP threads and the MPI ranks, checkpointed to
!!   OUTDIR/NAME.identify_mc.partial and resumed with --resume; the other ranks build the
!!   task from the deck and the payload rank 0 sends (identify_mc_task).
!! * The classical value beside it: I1_linear = m g b b' T^2 / (16 pi^2 l) (l the mean of
!!   the two cable lengths), T the period at the smallest amplitude or the record's mean
!!   period; linear_error = I1_linear / I1 - 1.
!!
!! Files: OUTDIR/NAME.identify (key = value lines, then the budget table of I1); with a
!! record also OUTDIR/NAME.fit.dat (t, measured, model, residual).  No routine stops.
!!
!! The analysis for the driver: identify_analysis_t (module analysis_base), which keeps
!! what its preconditions read (identify_input_t) for its run.
module identify
    use kinds, only: dp
    use status, only: status_t
    use deck, only: deck_t
    use output_io, only: out_files_t
    use budget, only: budget_row_t
    use, intrinsic :: iso_fortran_env, only: int64
    use records, only: record_t
    use measurement, only: measurement_t
    use sweep_engine, only: sweep_task_t, sweep_options_t, sweep_report_t
    use monte_carlo, only: MC_ANALYSIS
    use analysis_base, only: analysis_t, warning_t, WORD_LEN
    implicit none
    private

    public :: warning_t                         ! (of module analysis_base)

    !> What identify_ready read, kept for the run (a record read twice could be
    !! replaced in between, a logger still writing, and its second reading went unchecked):
    !! the measurement (module measurement: the deck's one release or a table's, their
    !! timings or records, the common inputs, the tares), each record read and checked once,
    !! with the CRC-64 of the record file's bytes as read; the releases that failed, where
    !! &measurement on_failure = 'skip', marked skipped.
    type, public :: identify_input_t
        logical :: ready = .false.              !! filled by identify_ready
        type(measurement_t) :: m                !! the measurement
    end type identify_input_t

    !> What identify found (deck units; the record's units for residuals).
    type, public :: identify_result_t
        logical :: from_record = .false.        !! a record fit (else periods)
        !> an uncertainty was given (a u of an input, the timings' scatter, a record's
        !! residuals, the releases' scatter); else u_I1 = 0 says nothing
        logical :: uncertainty_given = .true.
        integer(int64), allocatable :: record_crc(:)    !! each release's record's CRC-64
        !> I1 of the body (after tare and added inertia) and its combined standard u
        real(dp) :: i1 = 0.0_dp, u_i1 = 0.0_dp
        real(dp) :: u_i1_expanded = 0.0_dp      !! U = k u (95 %)
        real(dp) :: k = 0.0_dp                  !! coverage factor (Student's t, dof_eff)
        real(dp) :: dof_eff = 0.0_dp            !! Welch-Satterthwaite (NU_INFINITE: inf)
        !> I1 of all that hung (before tare and added inertia) and its u
        real(dp) :: i1_total = 0.0_dp, u_i1_total = 0.0_dp
        !> the part of u_I1 measured anew for this body (its timings, amplitudes, fits,
        !! releases and sessions: the budget's first n_own_rows rows) and its degrees of
        !! freedom (what a deck that takes this output as its tare needs)
        real(dp) :: u_i1_own = 0.0_dp, dof_own = 0.0_dp
        integer :: n_own_rows = 0
        real(dp) :: i1_tare_file = 0.0_dp       !! a tare read from its output (0: none)
        real(dp) :: u_i1_fit = 0.0_dp           !! the fit's part of u_I1 (record)
        real(dp) :: u_i1_random = 0.0_dp        !! the releases' random part (Type A)
        real(dp) :: u_i1_reproducibility = 0.0_dp   !! what their scatter added to it
        real(dp) :: birge_ratio = -1.0_dp, p_value = -1.0_dp    !! -1: not tested
        integer :: n_trials = 1                 !! releases pooled
        integer :: n_trials_skipped = 0         !! releases left out (on_failure = 'skip')
        character(len=14) :: consistency = 'single release'
        !> sessions: how many the releases name (0: none); with two or more, the releases
        !! pooled in two levels (module pooling): each session's label, I1 (all that hung)
        !! and u, the sessions' Birge ratio and p (-1: not tested), their consistency, and
        !! the sessions' part of u_I1 (the budget's row u_I1_session)
        integer :: n_sessions = 0
        character(len=64), allocatable :: session_label(:)
        real(dp), allocatable :: session_i1(:), session_u(:)
        real(dp) :: session_birge_ratio = -1.0_dp, session_p_value = -1.0_dp
        character(len=14) :: session_consistency = ''
        real(dp) :: u_i1_session = 0.0_dp
        !> Each fit's self-check against its stated u (module estimator): 'consistent',
        !! 'inconsistent' (chi^2's p < 0.05 in a release) or 'not tested' (u from the
        !! scatter or the residuals); the largest Birge ratio of the fits tested (-1: none)
        character(len=12) :: fit_consistency = 'not tested'
        real(dp) :: fit_birge_ratio = -1.0_dp
        real(dp) :: u_i1_mc = -1.0_dp, mc_mean = 0.0_dp     !! Monte Carlo (when asked)
        real(dp) :: i1_linear = 0.0_dp, linear_error = 0.0_dp
        real(dp) :: period_linear = 0.0_dp      !! the period the linear formula used (s)
        !> periods without u_period: the scatter of the timed totals about the model, s
        !! (used as u_period; -1 when u_period is given or there is one period)
        real(dp) :: u_period_scatter = -1.0_dp
        real(dp) :: residual_rms = 0.0_dp       !! of measured - model (s, rad or rad/s)
        integer :: iterations = 0, evaluations = 0, samples = 0
        integer :: np = 0                       !! parameters estimated
        character(len=16) :: names(6) = ''      !! their names (I1 first)
        real(dp) :: p(6) = 0.0_dp, u_p(6) = 0.0_dp  !! estimates and first-order u
        real(dp) :: sigma = 0.0_dp              !! s of the covariance (record)
        logical :: sigma_stated = .false.       !! s = 1: the record's column 3
        real(dp) :: correlation_time = 1.0_dp   !! of the residuals, samples (record)
        real(dp) :: n_effective = 0.0_dp        !! samples / correlation time (record)
        real(dp), allocatable :: model_periods(:)   !! T_i(I1) per cycle (periods)
        character(len=16) :: period_model = ''  !! 'exact torsion', 'simulated', 'record'
        logical :: periods_exact = .true.       !! periods of pure torsion (else simulated)
        character(len=64), allocatable :: trial_label(:)    !! each release's label
        character(len=64), allocatable :: trial_session(:)  !! its session ('' : none)
        !> the releases left out: each named with its row ("trial 'A' (line 3)")
        type(warning_t), allocatable :: skipped(:)
        real(dp), allocatable :: trial_i1(:), trial_u(:)    !! each release's I1 and own u
        type(budget_row_t), allocatable :: budget(:)
        real(dp), allocatable :: model(:)       !! the model at the record's times
        integer :: ifirst = 1                   !! first sample fitted (record)
        type(warning_t), allocatable :: warnings(:)
        real(dp) :: cpu_seconds = 0.0_dp
    end type identify_result_t

    !> The figure's data, as the analysis has it when it writes its data files: the timed
    !! periods (amplitude in degrees, period per cycle and its u, in s) with the model's
    !! curve; or a record (t, measured, model in the record's units).
    type :: cert_figure_data_t
        logical :: periods = .false., record = .false.
        real(dp), allocatable :: amp(:), per(:), u_per(:)       !! timed periods
        real(dp), allocatable :: curve_amp(:), curve_per(:)     !! the model at I1_total
        real(dp) :: classical = 0.0_dp                          !! the classical period
        real(dp), allocatable :: t(:), measured(:), model(:)    !! a record
        character(len=:), allocatable :: units                  !! the record's units
    end type cert_figure_data_t

    !> Analysis `identify` (module analysis_base): OUTDIR/NAME.identify with NAME.fit.dat (a
    !! record) or NAME.periods.dat (periods); its Monte Carlo the sweep MC_ANALYSIS
    !! (checkpoint OUTDIR/NAME.identify_mc.partial); its part of the summary line: I1 with
    !! its expanded uncertainty, the other parameters, the releases, the period model, the
    !! Monte Carlo, the linear formula, the iterations.
    type, extends(analysis_t), public :: identify_analysis_t
        type(identify_input_t) :: input         !! what its preconditions read
        type(identify_result_t) :: res          !! what it found
        type(sweep_report_t) :: rep             !! how its Monte Carlo's sweep went
    contains
        procedure, nopass :: word => identify_word
        procedure, nopass :: owned_extensions => identify_owned
        procedure, nopass :: sweeps => identify_sweeps
        procedure :: ready => identify_analysis_ready
        procedure :: run => identify_analysis_run
        procedure :: summary => identify_summary
        procedure :: sweep_task => identify_sweep_task
    end type identify_analysis_t

    public :: identify_ready, run_identify, identify_record, identify_mc_task

    interface
        !> OUTDIR/NAME.certificate.html (submodule identify_certificate): the page an
        !! engineer attaches to a test report, into the run's files.
        module subroutine write_identify_certificate(d, outdir, res, fig, files, stat)
            type(deck_t), intent(in) :: d
            character(len=*), intent(in) :: outdir
            type(identify_result_t), intent(in) :: res
            type(cert_figure_data_t), intent(in) :: fig
            type(out_files_t), intent(inout) :: files
            type(status_t), intent(out) :: stat
        end subroutine write_identify_certificate
        !> The preconditions of analyses = 'identify', checked before any computing; the
        !! releases and records read once into `input` for run_identify; the work estimated
        !! (a note on stderr when it is long).
        module subroutine identify_ready(d, stat, input)
            type(deck_t), intent(in) :: d           !! the deck
            type(status_t), intent(out) :: stat     !! ERR_DECK, ERR_MODEL
            type(identify_input_t), intent(out), optional :: input  !! what was read
        end subroutine identify_ready

        !> Run analyses = 'identify' for a deck: OUTDIR/NAME.identify (and NAME.fit.dat).
        module subroutine run_identify(d, outdir, res, stat, files, options, report, input)
            type(deck_t), intent(in) :: d           !! the deck (identify_ready passed)
            character(len=*), intent(in) :: outdir  !! output directory
            type(identify_result_t), intent(out) :: res
            type(status_t), intent(out) :: stat     !! ERR_DECK, ERR_NUMERIC, ERR_IO
            type(out_files_t), intent(inout) :: files   !! the run's files
            type(sweep_options_t), intent(in), optional :: options  !! --resume, the interval
            type(sweep_report_t), intent(out), optional :: report   !! of the Monte Carlo
            !> what identify_ready read (else the releases are read here, once)
            type(identify_input_t), intent(in), optional :: input
        end subroutine run_identify

        !> I1 (and the other parameters asked for) from a record: the fit, the first-order
        !! budget, Monte Carlo when asked.
        module subroutine identify_record(d, rec, res, stat, outdir, options, report, files)
            type(deck_t), intent(in) :: d
            type(record_t), intent(in) :: rec
            type(identify_result_t), intent(out) :: res
            type(status_t), intent(out) :: stat
            character(len=*), intent(in), optional :: outdir
            type(sweep_options_t), intent(in), optional :: options
            type(sweep_report_t), intent(inout), optional :: report
            type(out_files_t), intent(in), optional :: files
        end subroutine identify_record

        !> The task of identify's Monte Carlo (sweep 'identify_mc') as the other ranks of an
        !! MPI run build it.
        module subroutine identify_mc_task(d, payload, task, stat)
            type(deck_t), intent(in) :: d           !! the deck
            real(dp), intent(in) :: payload(:)      !! the sweep's payload
            class(sweep_task_t), allocatable, intent(out) :: task
            type(status_t), intent(out) :: stat     !! ERR_DECK
        end subroutine identify_mc_task

        !> The preconditions (identify_ready), what they read kept for the run.
        module subroutine identify_analysis_ready(self, d, stat)
            class(identify_analysis_t), intent(inout) :: self
            type(deck_t), intent(in) :: d           !! the deck
            type(status_t), intent(out) :: stat     !! ERR_DECK, ERR_MODEL
        end subroutine identify_analysis_ready

        !> The run (run_identify into the run's files, from what ready read); the Monte
        !! Carlo's warning and the result's warnings kept.
        module subroutine identify_analysis_run(self, d, outdir, files, stat, options)
            class(identify_analysis_t), intent(inout) :: self
            type(deck_t), intent(in) :: d           !! the deck (ready passed)
            character(len=*), intent(in) :: outdir  !! output directory
            type(out_files_t), intent(inout) :: files   !! the run's files
            type(status_t), intent(out) :: stat     !! ERR_DECK, ERR_NUMERIC, ERR_IO
            type(sweep_options_t), intent(in), optional :: options  !! --resume, the interval
        end subroutine identify_analysis_run

        !> ' identify I1 = ... ± U (k = K, 95 %)..., N iterations;'
        module function identify_summary(self, d) result(s)
            class(identify_analysis_t), intent(in) :: self
            type(deck_t), intent(in) :: d           !! the deck (&measurement monte_carlo)
            character(len=:), allocatable :: s
        end function identify_summary

        !> The task of its Monte Carlo on the other ranks of an MPI run (identify_mc_task).
        module subroutine identify_sweep_task(self, sweep, d, payload, task, stat)
            class(identify_analysis_t), intent(in) :: self
            character(len=*), intent(in) :: sweep   !! MC_ANALYSIS
            type(deck_t), intent(in) :: d           !! the deck
            real(dp), intent(in) :: payload(:)      !! the sweep's payload
            class(sweep_task_t), allocatable, intent(out) :: task
            type(status_t), intent(out) :: stat     !! ERR_DECK
        end subroutine identify_sweep_task
    end interface

contains

    !> The word of &scene analyses.
    function identify_word() result(w)
        character(len=:), allocatable :: w
        w = 'identify'
    end function identify_word

    !> The files it writes: NAME.identify, NAME.fit.dat, NAME.periods.dat,
    !! NAME.certificate.html.
    subroutine identify_owned(names)
        character(len=WORD_LEN), allocatable, intent(out) :: names(:)
        names = [character(len=WORD_LEN) :: '.identify', '.fit.dat', '.periods.dat', &
                 '.certificate.html']
    end subroutine identify_owned

    !> Its sweep: the Monte Carlo (MC_ANALYSIS).
    subroutine identify_sweeps(names)
        character(len=WORD_LEN), allocatable, intent(out) :: names(:)
        names = [character(len=WORD_LEN) :: MC_ANALYSIS]
    end subroutine identify_sweeps

end module identify
