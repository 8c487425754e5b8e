!> The whole inertia tensor from several hangs (analysis tensor).
!!
!! A bifilar hang measures one number, the moment of inertia about the vertical through the
!! mass centre.  Hung in six or more orientations (&tensor hangs: a table of hangs, module
!! hang_table), the body gives the six entries of its tensor about the mass centre in the
!! user's body frame.  Each hang's period comes from the paper's full model of that hang
!! (module hang_model: the torsion mode of the linearised model at small amplitude, the
!! full model's period at the timed amplitude), so the coupling of torsion with tilting and
!! sway when the vertical is not a principal axis is in the fit; the projection solution
!! the linear formula gives is reported beside it.  The fit, its first-order uncertainty,
!! the amplitude limit of a hang, the plan of hangs and the Monte Carlo are module
!! tensor_fit's.
!!
!! Files: OUTDIR/NAME.tensor (key = value lines, then the budget), OUTDIR/NAME.tensor.dat
!! (per hang the measured and the fitted vertical moment, for plots/tensor.gp), and with
!! &tensor plan = N, OUTDIR/NAME.plan.csv (a table of hangs to copy).  No routine stops.
module tensor
    use kinds, only: dp
    use status, only: status_t
    use deck, only: deck_t
    use output_io, only: out_files_t
    use sweep_engine, only: sweep_task_t, sweep_options_t, sweep_report_t
    implicit none
    private

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
        integer :: plan = 0                     !! hangs planned (0: none)
        character(len=:), allocatable :: plan_file
        !> one line for standard error when the hangs disagree with the fit ('' when not)
        character(len=:), allocatable :: warning
        real(dp) :: cpu_seconds = 0.0_dp
    end type tensor_result_t

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
    end interface

end module tensor
