!> Whether a fitted model follows a record: the test every record fit passes before its
!! numbers are believed.
!!
!! A model that follows its record leaves residuals that are small beside the signal and
!! carry no trace of the swing.  Two signs that it does not:
!! * the residuals' rms is above FOLLOW_RMS_MAX (20 %) of the record's rms about its mean
!!   (module stats' rms_about_mean): the model misses the motion itself;
!! * the residuals' sample autocorrelation at a lag of one period (module stats'
!!   autocorrelation) is above FOLLOW_RHO_MAX (0.5): what is left still swings with the
!!   rig, a decay, a phase or an amplitude the model cannot take.
!! The likely causes, in the order a user checks them: a parameter missing from
!! &measurement estimate (the damping, a bias, the amplitude, the release time),
!! record_units, the axis (the record's column), the release time, the mass centre.
module model_follow
    use kinds, only: dp
    use stats, only: autocorrelation, rms_about_mean
    use text, only: sci, fixed, itoa
    implicit none
    private

    real(dp), parameter, public :: FOLLOW_RMS_MAX = 0.2_dp  !! residual rms over the record's
    real(dp), parameter, public :: FOLLOW_RHO_MAX = 0.5_dp  !! autocorrelation at one period

    public :: follows_record, not_following_message

contains

    !> ok: whether the residuals e of a record v (same units, same samples) show a model that
    !! follows it; ratio: rms(e) over the rms of v about its mean; rho: the residuals'
    !! autocorrelation at lag samples (one period; 0 when lag < 1).
    pure subroutine follows_record(v, e, lag, ok, ratio, rho)
        real(dp), intent(in) :: v(:), e(:)
        integer, intent(in) :: lag
        logical, intent(out) :: ok
        real(dp), intent(out) :: ratio, rho
        real(dp) :: rv
        rv = rms_about_mean(v)
        ratio = 0.0_dp
        if (rv > 0.0_dp .and. size(e) > 0) ratio = sqrt(sum(e**2)/size(e))/rv
        rho = autocorrelation(e, lag)
        ok = .not. (ratio > FOLLOW_RMS_MAX .or. rho > FOLLOW_RHO_MAX)
    end subroutine follows_record

    !> The one line of a refused record fit: what was measured and the likely causes in
    !! order.
    function not_following_message(ratio, rho, lag, missing) result(msg)
        real(dp), intent(in) :: ratio, rho
        integer, intent(in) :: lag
        character(len=*), intent(in) :: missing     !! parameters not estimated ('' : none)
        character(len=:), allocatable :: msg
        character(len=:), allocatable :: first
        first = 'a parameter missing from &measurement estimate'
        if (len_trim(missing) > 0) first = first//' (not estimated: '//trim(missing)//')'
        msg = 'identify: the fitted model does not follow the record (residual rms '// &
            fixed(100.0_dp*ratio, 1)//' % of the record''s rms about its mean, allowed '// &
            fixed(100.0_dp*FOLLOW_RMS_MAX, 0)//' %; residual autocorrelation at one period ('// &
            itoa(lag)//' samples) '//sci(rho, 2)//', allowed '//fixed(FOLLOW_RHO_MAX, 2)// &
            '); likely causes, in order: '//first//', record_units, the axis (the record''s '// &
            'column), the release time (&start, t0), the mass centre (cg_depth)'
    end function not_following_message

end module model_follow
