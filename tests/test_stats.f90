!> The statistics of uncertainty statements (module stats) against published values:
!! Student's t quantiles (GUM table G.2 and more digits from standard tables), the normal
!! quantile, chi-square tail probabilities at the tabulated 5 % points, the incomplete beta
!! function's symmetry, Welch-Satterthwaite, the weighted mean and its Birge ratio.
module test_stats
    use kinds, only: dp
    use testing, only: tester_t
    use stats, only: t_cdf, t_quantile, coverage_factor, normal_quantile, chi2_sf, &
        welch_satterthwaite, incomplete_beta, weighted_mean, NU_INFINITE
    use unused_arg, only: unused
    implicit none
    private

    public :: run_stats_tests

contains

    !> Suite stats.
    subroutine run_stats_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        call unused(exe)
        if (t%want('stats: Student''s t and the normal quantiles against tables')) &
            call test_quantiles(t)
        if (t%want('stats: chi-square tails, incomplete beta, Welch-Satterthwaite, '// &
                   'weighted mean')) call test_others(t)
    end subroutine run_stats_tests

    subroutine test_quantiles(t)
        type(tester_t), intent(inout) :: t
        real(dp), parameter :: NU(6) = [1.0_dp, 2.0_dp, 4.0_dp, 10.0_dp, 30.0_dp, 100.0_dp]
        ! t_0.975 for those nu (standard tables, 7 digits or more)
        real(dp), parameter :: T975(6) = [12.7062047_dp, 4.30265273_dp, 2.77644511_dp, &
                                          2.22813885_dp, 2.04227246_dp, 1.98397152_dp]
        integer :: i
        do i = 1, size(NU)
            call t%check_close('t quantile 0.975, nu = '//trim(num(NU(i))), &
                               t_quantile(0.975_dp, NU(i)), T975(i), rtol=1.0e-7_dp)
        end do
        call t%check_close('t quantile 0.995, nu = 5', t_quantile(0.995_dp, 5.0_dp), &
                           4.03214300_dp, rtol=1.0e-7_dp)
        call t%check_close('t quantile 0.025 = -t 0.975 (nu = 3)', t_quantile(0.025_dp, 3.0_dp), &
                           -3.18244631_dp, rtol=1.0e-7_dp)
        call t%check('t quantile, nu = 2.5 between those of nu = 2 and 3', &
                     t_quantile(0.975_dp, 2.5_dp) < T975(2) .and. &
                     t_quantile(0.975_dp, 2.5_dp) > 3.18244631_dp)
        call t%check_close('normal quantile 0.975', normal_quantile(0.975_dp), 1.95996398_dp, &
                           rtol=1.0e-8_dp)
        call t%check_close('normal quantile 0.8413447 = 1', normal_quantile(0.841344746_dp), &
                           1.0_dp, rtol=1.0e-7_dp)
        call t%check_close('coverage factor 95 %, nu infinite', &
                           coverage_factor(NU_INFINITE, 0.95_dp), 1.95996398_dp, rtol=1.0e-8_dp)
        call t%check_close('coverage factor 95 %, nu = 10', coverage_factor(10.0_dp, 0.95_dp), &
                           2.22813885_dp, rtol=1.0e-7_dp)
        call t%check_close('t cdf inverts the quantile (nu = 7)', &
                           t_cdf(t_quantile(0.9_dp, 7.0_dp), 7.0_dp), 0.9_dp, rtol=1.0e-12_dp)
    end subroutine test_quantiles

    subroutine test_others(t)
        type(tester_t), intent(inout) :: t
        real(dp) :: mean, u_int, chi2, birge
        call t%check_close('chi2 tail at its 5 % point, k = 1', chi2_sf(3.84145882_dp, 1.0_dp), &
                           0.05_dp, rtol=1.0e-7_dp)
        call t%check_close('chi2 tail at its 5 % point, k = 5', chi2_sf(11.0704977_dp, 5.0_dp), &
                           0.05_dp, rtol=1.0e-7_dp)
        call t%check_close('chi2 tail at its 5 % point, k = 10', chi2_sf(18.3070381_dp, &
                           10.0_dp), 0.05_dp, rtol=1.0e-7_dp)
        call t%check_close('chi2 tail at its 1 % point, k = 20', chi2_sf(37.5662347_dp, &
                           20.0_dp), 0.01_dp, rtol=1.0e-7_dp)
        call t%check_close('chi2 tail of 0 is 1', chi2_sf(0.0_dp, 3.0_dp), 1.0_dp, rtol=0.0_dp)
        call t%check_close('incomplete beta I_1/2(a, a) = 1/2', incomplete_beta(0.5_dp, &
                           3.7_dp, 3.7_dp), 0.5_dp, rtol=1.0e-13_dp)
        call t%check_close('incomplete beta I_x(1, 1) = x', incomplete_beta(0.3_dp, 1.0_dp, &
                           1.0_dp), 0.3_dp, rtol=1.0e-13_dp)
        call t%check_close('Welch-Satterthwaite: u = 1, 1 with nu = 4, infinite gives 16', &
                           welch_satterthwaite([1.0_dp, 1.0_dp], [4.0_dp, 0.0_dp]), 16.0_dp, &
                           rtol=1.0e-14_dp)
        call t%check('Welch-Satterthwaite: all infinite gives NU_INFINITE', &
                     welch_satterthwaite([1.0_dp, 2.0_dp], [0.0_dp, 0.0_dp]) == NU_INFINITE)
        call weighted_mean([1.0_dp, 3.0_dp], [1.0_dp, 1.0_dp], mean, u_int, chi2, birge)
        call t%check_close('weighted mean of 1 and 3 (equal u)', mean, 2.0_dp, rtol=1.0e-15_dp)
        call t%check_close('its internal u = 1/sqrt(2)', u_int, sqrt(0.5_dp), rtol=1.0e-15_dp)
        call t%check_close('its chi2 = 2, Birge ratio = sqrt(2)', birge, sqrt(2.0_dp), &
                           rtol=1.0e-15_dp)
    end subroutine test_others

    pure function num(x) result(s)
        real(dp), intent(in) :: x
        character(len=16) :: s
        write (s, '(f0.1)') x
    end function num

end module test_stats
