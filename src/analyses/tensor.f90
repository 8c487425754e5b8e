!> The whole inertia tensor from several hangs (analysis tensor).
!!
!! A bifilar hang measures one number, the moment of inertia about the vertical through the
!! mass centre.  Hung in six or more orientations (&tensor hangs: a table of hangs, read
!! into the measurement's model by module measurement_read), the body gives the six entries of its tensor about the mass centre in the
!! user's body frame.  Each hang's period comes from the paper's full model of that hang
!! (module hang_model: the torsion mode of the linearised model at small amplitude, the
!! full model's period at the timed amplitude), so the coupling of torsion with tilting and
!! sway when the vertical is not a principal axis is in the fit; the projection solution
!! the linear formula gives is reported beside it.  The fit, its first-order uncertainty,
!! the amplitude limit of a hang, the plan of hangs and the Monte Carlo are module
!! tensor_fit's.
!!
!! Files: OUTDIR/NAME.tensor (key = value lines, then the budget), OUTDIR/NAME.tensor.dat
!! (per hang the measured and the fitted vertical moment, for plots/tensor.gp),
!! OUTDIR/NAME.certificate.html (submodule tensor_certificate, when a table of hangs was
!! fitted), and with &tensor plan = N, OUTDIR/NAME.plan.csv (a table of hangs to copy).
!! No routine stops.
!!
!! The analysis for the driver: tensor_analysis_t (module analysis_base).
module tensor
    use kinds, only: dp
    use status, only: status_t
    use deck, only: deck_t
    use output_io, only: out_files_t
    use sweep_engine, only: sweep_task_t, sweep_options_t, sweep_report_t
    use monte_carlo, only: MC_TENSOR
    use analysis_base, only: analysis_t, WORD_LEN
    implicit none
    private

    !> One warning line.
    type, public :: tensor_line_t
        character(len=:), allocatable :: s
    end type tensor_line_t

    !> What the analysis found (deck units; the summary line's parts).
    type, public :: tensor_result_t
        logical :: fitted = .false.             !! a table of hangs was fitted
        real(dp) :: moments(3) = 0.0_dp         !! principal moments, ascending
        real(dp) :: u_moments(3) = 0.0_dp
        real(dp) :: chi2 = 0.0_dp, p_value = 1.0_dp
        integer :: dof = 0
        real(dp) :: projection_difference = 0.0_dp
        integer :: hangs = 0, rows = 0
        integer :: mc_samples = 0               !! Monte Carlo samples (0: none)
        real(dp) :: u_moments_mc(3) = 0.0_dp
        !> with the mass centre fitted: the Monte Carlo's mean of cg and its u (body frame)
        real(dp) :: cg_mc(3) = 0.0_dp, u_cg_mc(3) = 0.0_dp
        integer :: plan = 0                     !! hangs planned (0: none)
        character(len=:), allocatable :: plan_file
        !> one line for standard error when the hangs disagree with the fit ('' when not)
        character(len=:), allocatable :: warning
        !> more warning lines: hangs nearly parallel, moments near the triangle inequality
        type(tensor_line_t), allocatable :: warnings(:)
        real(dp) :: cpu_seconds = 0.0_dp
    end type tensor_result_t

    !> Analysis `tensor` (module analysis_base): OUTDIR/NAME.tensor, NAME.tensor.dat (and
    !! NAME.plan.csv); its Monte Carlo the sweep MC_TENSOR (checkpoint
    !! OUTDIR/NAME.tensor_mc.partial); its part of the summary line: the principal moments
    !! with their u, the chi-square, how far the projection solution lies, the Monte Carlo,
    !! the plan.
    type, extends(analysis_t), public :: tensor_analysis_t
        type(tensor_result_t) :: res            !! what it found
        type(sweep_report_t) :: rep             !! how its Monte Carlo's sweep went
    contains
        procedure, nopass :: word => tensor_word
        procedure, nopass :: owned_extensions => tensor_owned
        procedure, nopass :: sweeps => tensor_sweeps
        procedure :: ready => tensor_analysis_ready
        procedure :: run => tensor_analysis_run
        procedure :: summary => tensor_summary
        procedure :: sweep_task => tensor_analysis_sweep_task
    end type tensor_analysis_t

    public :: tensor_ready, run_tensor, tensor_sweep_task

    interface
        !> The preconditions of analyses = 'tensor', checked before any computing: the
        !! paper's model; the table of hangs readable and sound, each hang's rig able to
        !! hang the body, the directions determining the tensor; a plan's rig.
        module subroutine tensor_ready(d, stat)
            type(deck_t), intent(in) :: d           !! the deck
            type(status_t), intent(out) :: stat     !! ERR_DECK; ERR_MODEL: a period no rig gives
        end subroutine tensor_ready

        !> Run analyses = 'tensor' for a deck: OUTDIR/NAME.tensor, NAME.tensor.dat (and
        !! NAME.plan.csv) into `files`; the Monte Carlo a sweep checkpointed to
        !! OUTDIR/NAME.tensor_mc.partial (options: --resume, the interval; report: how its
        !! sweep went).
        module subroutine run_tensor(d, outdir, res, stat, files, options, report)
            type(deck_t), intent(in) :: d           !! the deck (tensor_ready passed)
            character(len=*), intent(in) :: outdir  !! output directory
            type(tensor_result_t), intent(out) :: res
            type(status_t), intent(out) :: stat     !! ERR_DECK, ERR_NUMERIC, ERR_MODEL, ERR_IO
            type(out_files_t), intent(inout) :: files   !! the run's files
            type(sweep_options_t), intent(in), optional :: options
            type(sweep_report_t), intent(out), optional :: report
        end subroutine run_tensor

        !> The task of tensor's Monte Carlo (sweep 'tensor_mc') as the other ranks of an MPI
        !! run build it from the deck and the sweep's payload.
        module subroutine tensor_sweep_task(d, payload, task, stat)
            type(deck_t), intent(in) :: d           !! the deck
            real(dp), intent(in) :: payload(:)      !! the sweep's payload
            class(sweep_task_t), allocatable, intent(out) :: task
            type(status_t), intent(out) :: stat     !! ERR_DECK
        end subroutine tensor_sweep_task

        !> OUTDIR/NAME.certificate.html (submodule tensor_certificate): the page an
        !! engineer attaches to a test report, for a deck that fitted a table of hangs.
        module subroutine write_tensor_certificate(d, outdir, res, fit, prob, drift, limit, &
                                                   u_x_mc, u_moments_mc, files, stat)
            type(deck_t), intent(in) :: d           !! the deck
            character(len=*), intent(in) :: outdir  !! output directory
            type(tensor_result_t), intent(in) :: res
            !> the fit (tensor_fit_t) and its problem, the hangs and timings
            !! (tensor_problem_t) of module tensor_fit: unlimited polymorphic here, so that
            !! this module, which the driver uses, stays below tensor_fit's floor
            class(*), intent(in) :: fit, prob
            real(dp), intent(in) :: drift(:), limit(:)  !! per timing, per hang
            real(dp), intent(in) :: u_x_mc(6), u_moments_mc(3)  !! Monte Carlo (0: none)
            type(out_files_t), intent(inout) :: files   !! the run's files
            type(status_t), intent(out) :: stat     !! ERR_IO; ERR_NUMERIC: not those types
        end subroutine write_tensor_certificate

        !> The preconditions (tensor_ready).
        module subroutine tensor_analysis_ready(self, d, stat)
            class(tensor_analysis_t), intent(inout) :: self
            type(deck_t), intent(in) :: d           !! the deck
            type(status_t), intent(out) :: stat     !! ERR_DECK, ERR_MODEL
        end subroutine tensor_analysis_ready

        !> The run (run_tensor into the run's files); the Monte Carlo's warning and the
        !! result's warning kept.
        module subroutine tensor_analysis_run(self, d, outdir, files, stat, options)
            class(tensor_analysis_t), intent(inout) :: self
            type(deck_t), intent(in) :: d           !! the deck (ready passed)
            character(len=*), intent(in) :: outdir  !! output directory
            type(out_files_t), intent(inout) :: files   !! the run's files
            type(status_t), intent(out) :: stat     !! ERR_DECK, ERR_NUMERIC, ERR_MODEL, ERR_IO
            type(sweep_options_t), intent(in), optional :: options  !! --resume, the interval
        end subroutine tensor_analysis_run

        !> ' tensor I_principal = ... (u ...), chi2 .../dof N, N hangs, projection off by
        !! ...[, Monte Carlo u ...][, a plan of N hangs in FILE];'
        module function tensor_summary(self, d) result(s)
            class(tensor_analysis_t), intent(in) :: self
            type(deck_t), intent(in) :: d           !! the deck
            character(len=:), allocatable :: s
        end function tensor_summary

        !> The task of its Monte Carlo on the other ranks of an MPI run (tensor_sweep_task).
        module subroutine tensor_analysis_sweep_task(self, sweep, d, payload, task, stat)
            class(tensor_analysis_t), intent(in) :: self
            character(len=*), intent(in) :: sweep   !! MC_TENSOR
            type(deck_t), intent(in) :: d           !! the deck
            real(dp), intent(in) :: payload(:)      !! the sweep's payload
            class(sweep_task_t), allocatable, intent(out) :: task
            type(status_t), intent(out) :: stat     !! ERR_DECK
        end subroutine tensor_analysis_sweep_task
    end interface

contains

    !> The word of &scene analyses.
    function tensor_word() result(w)
        character(len=:), allocatable :: w
        w = 'tensor'
    end function tensor_word

    !> The files it writes: NAME.tensor, NAME.tensor.dat, NAME.plan.csv.
    subroutine tensor_owned(names)
        character(len=WORD_LEN), allocatable, intent(out) :: names(:)
        names = [character(len=WORD_LEN) :: '.tensor', '.tensor.dat', '.plan.csv']
    end subroutine tensor_owned

    !> Its sweep: the Monte Carlo (MC_TENSOR).
    subroutine tensor_sweeps(names)
        character(len=WORD_LEN), allocatable, intent(out) :: names(:)
        names = [character(len=WORD_LEN) :: MC_TENSOR]
    end subroutine tensor_sweeps

end module tensor
