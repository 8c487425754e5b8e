!> Analysis calibrate: the rig's effective constants from a reference swung on it (a body
!! of known moment, or a test mass at known radii; &calibration), its swings given in
!! &measurement as identify takes timed periods (periods or a table of releases).  The
!! constants, an effective-length offset delta_l and a scale s of b b' (R R' on a
!! platform), are estimated with the moment of the reference (and the test mass) by the
!! one estimator (module estimator): residuals the periods' misfits over their u and the
!! reference's own statement, so chi^2 tests them.  Releases at one cable length cannot
!! separate delta_l from s (the estimator's rank note): delta_l is then held at 0.
!! Writes OUTDIR/NAME.calibration (key = value, doc/output.md) and
!! OUTDIR/NAME.certificate.html.
module calibrate
    use kinds, only: dp
    use status, only: status_t
    use deck, only: deck_t
    use output_io, only: out_files_t
    use measurement, only: measurement_t
    use sweep_engine, only: sweep_options_t
    use rig_calibration, only: rig_calibration_t
    use analysis_base, only: analysis_t, WORD_LEN
    implicit none
    private

    !> What calibrate found.
    type, public :: calibrate_result_t
        type(rig_calibration_t) :: cal          !! the constants and their covariance
        real(dp) :: i_reference = 0.0_dp, u_i_reference = 0.0_dp   !! the reference's I1
        real(dp) :: test_mass = 0.0_dp, u_test_mass = 0.0_dp        !! (a test mass)
        real(dp) :: p_value = 1.0_dp, birge = 0.0_dp
        logical :: consistent = .true.
        character(len=:), allocatable :: not_separable  !! the rank note ('' : none)
        integer :: n_periods = 0, n_releases = 0
    end type calibrate_result_t

    type, extends(analysis_t), public :: calibrate_analysis_t
        type(measurement_t) :: m                !! the reference's swings
        type(calibrate_result_t) :: res
    contains
        procedure, nopass :: word => calibrate_word
        procedure, nopass :: owned_extensions => calibrate_owned
        procedure :: ready => calibrate_ready
        procedure :: run => calibrate_run
        procedure :: summary => calibrate_summary
    end type calibrate_analysis_t

    interface
        module subroutine calibrate_ready(self, d, stat)
            class(calibrate_analysis_t), intent(inout) :: self
            type(deck_t), intent(in) :: d
            type(status_t), intent(out) :: stat
        end subroutine calibrate_ready
        module subroutine calibrate_run(self, d, outdir, files, stat, options)
            class(calibrate_analysis_t), intent(inout) :: self
            type(deck_t), intent(in) :: d
            character(len=*), intent(in) :: outdir
            type(out_files_t), intent(inout) :: files
            type(status_t), intent(out) :: stat
            type(sweep_options_t), intent(in), optional :: options
        end subroutine calibrate_run
        module function calibrate_summary(self, d) result(s)
            class(calibrate_analysis_t), intent(in) :: self
            type(deck_t), intent(in) :: d
            character(len=:), allocatable :: s
        end function calibrate_summary
    end interface

contains

    function calibrate_word() result(w)
        character(len=:), allocatable :: w
        w = 'calibrate'
    end function calibrate_word

    subroutine calibrate_owned(names)
        character(len=WORD_LEN), allocatable, intent(out) :: names(:)
        ! (NAME.certificate.html, which it also writes, is registered once, by identify)
        names = [character(len=WORD_LEN) :: '.calibration']
    end subroutine calibrate_owned

end module calibrate
