!> One result from several releases: the pooled estimate, its random (Type A) standard
!! uncertainty with its degrees of freedom, and whether the releases agree.
!!
!! Each release r gives an estimate x_r with its own standard uncertainty u_r (what that
!! release alone knows: its timing scatter, its record's noise, the inputs measured anew for
!! it) on nu_r degrees of freedom.  Components common to every release (mass, g, one
!! tape's calibration) are not here: they enter the final budget once, not averaged down.
!!
!! * Consistency: chi^2 = sum w_r (x_r - xbar_w)^2 with w_r = 1/u_r^2 and xbar_w the
!!   weighted mean; the Birge ratio R_B = (chi^2/(n - 1))^(1/2); the releases disagree when
!!   P(chi^2_{n-1} >= chi^2) < 0.05.
!! * Consistent releases: the weighted mean, u_int = (sum w_r)^(-1/2) with the
!!   Welch-Satterthwaite degrees of freedom of its parts.
!! * Inconsistent releases: the scatter between them is a component of its own (the
!!   reproducibility of a release, tau^2, by the method of moments of DerSimonian and Laird,
!!   Controlled Clinical Trials 7 (1986) 177): weights 1/(u_r^2 + tau^2), u of that mean
!!   (sum 1/(u_r^2 + tau^2))^(-1/2), n - 1 degrees of freedom.
!! * Releases without their own u (one timed period each, say): the plain mean, untested.
!! * In every case the random u is never below the standard error of the releases' mean,
!!   s/n^(1/2) (s their standard deviation), which then carries n - 1 degrees of freedom.
!!   u_reproducibility = (u_random^2 - u_int^2)^(1/2) is what the scatter added.
module pooling
    use kinds, only: dp
    use stats, only: chi2_sf, NU_INFINITE
    implicit none
    private

    !> Level of the chi-square test of consistency.
    real(dp), parameter, public :: CONSISTENCY_LEVEL = 0.05_dp

    !> Several releases pooled.
    type, public :: pooled_t
        integer :: n = 0                        !! releases
        real(dp) :: mean = 0.0_dp               !! the pooled estimate
        real(dp) :: u_int = 0.0_dp              !! from the releases' own u
        real(dp) :: sem = 0.0_dp                !! standard error of the releases' mean
        real(dp) :: chi2 = 0.0_dp, birge = -1.0_dp, p_value = -1.0_dp   !! -1: not tested
        real(dp) :: tau = 0.0_dp                !! reproducibility of one release (0: none)
        real(dp) :: u_random = 0.0_dp           !! the pooled estimate's random u
        real(dp) :: nu_random = NU_INFINITE     !! its degrees of freedom
        real(dp) :: u_reproducibility = 0.0_dp  !! (u_random^2 - u_int^2)^(1/2)
        real(dp), allocatable :: weight(:)      !! each release's weight (sum 1)
        !> 'single release', 'consistent', 'inconsistent' or 'not tested'
        character(len=14) :: consistency = 'single release'
    end type pooled_t

    public :: pool_releases

contains

    !> Pool n >= 1 releases (see the module header).
    pure subroutine pool_releases(x, u, nu, pool)
        real(dp), intent(in) :: x(:)            !! each release's estimate
        real(dp), intent(in) :: u(:)            !! its own standard uncertainty (>= 0)
        real(dp), intent(in) :: nu(:)           !! its degrees of freedom (NU_INFINITE: B)
        type(pooled_t), intent(out) :: pool
        real(dp) :: w(size(x)), ws, s, xbar, t2, part(size(x))
        integer :: n
        n = size(x)
        pool%n = n
        allocate (pool%weight(n))
        if (n == 1) then
            pool%mean = x(1)
            pool%u_int = u(1)
            pool%u_random = u(1)
            pool%nu_random = nu(1)
            pool%weight = 1.0_dp
            return
        end if
        xbar = sum(x)/n
        s = sqrt(sum((x - xbar)**2)/(n - 1))
        pool%sem = s/sqrt(real(n, dp))
        if (all(u > 0.0_dp)) then
            w = 1.0_dp/u**2
            ws = sum(w)
            pool%mean = sum(w*x)/ws
            pool%u_int = 1.0_dp/sqrt(ws)
            pool%chi2 = sum(w*(x - pool%mean)**2)
            pool%birge = sqrt(pool%chi2/(n - 1))
            pool%p_value = chi2_sf(pool%chi2, real(n - 1, dp))
            if (pool%p_value >= CONSISTENCY_LEVEL) then
                pool%consistency = 'consistent'
                pool%weight = w/ws
                pool%u_random = pool%u_int
                part = pool%weight*u
                pool%nu_random = min(NU_INFINITE, pool%u_int**4/sum(part**4/nu))
            else
                pool%consistency = 'inconsistent'
                t2 = max(0.0_dp, (pool%chi2 - (n - 1))/(ws - sum(w**2)/ws))
                pool%tau = sqrt(t2)
                w = 1.0_dp/(u**2 + t2)
                pool%weight = w/sum(w)
                pool%mean = sum(w*x)/sum(w)
                pool%u_random = 1.0_dp/sqrt(sum(w))
                pool%nu_random = n - 1
            end if
        else
            pool%consistency = 'not tested'
            pool%mean = xbar
            pool%weight = 1.0_dp/n
            pool%u_int = sqrt(sum(u**2))/n
            pool%u_random = pool%u_int
            pool%nu_random = n - 1
        end if
        if (pool%sem > pool%u_random) then
            pool%u_random = pool%sem
            pool%nu_random = n - 1
        end if
        pool%u_reproducibility = sqrt(max(0.0_dp, pool%u_random**2 - pool%u_int**2))
    end subroutine pool_releases

end module pooling
