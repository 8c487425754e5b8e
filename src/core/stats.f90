!> The statistics of an uncertainty statement (GUM, JCGM 100:2008, annex G): Student's t
!! and its quantiles (coverage factors), the chi-square distribution's upper tail (p-values
!! of consistency tests), Welch-Satterthwaite's effective degrees of freedom, and the
!! weighted mean of several results with its Birge ratio.
!!
!! Written from the published definitions:
!! * Student's t with nu degrees of freedom: P(|T| <= t) = 1 - I_x(nu/2, 1/2),
!!   x = nu/(nu + t^2), I_x(a, b) the regularized incomplete beta function, evaluated by its
!!   continued fraction (Abramowitz & Stegun 26.5.8) with the modified Lentz method
!!   (Thompson & Barnett, J. Comput. Phys. 64, 1986); quantiles by bisection refined by
!!   Newton's method on the density.
!! * The normal distribution through the intrinsic erfc; its quantile by Newton's method.
!! * Chi-square with k degrees of freedom: P(X > x) = Q(k/2, x/2), the regularized upper
!!   incomplete gamma function, by its series for x < a + 1 and by its continued fraction
!!   otherwise (A&S 6.5.29, 6.5.31).
!! * Welch-Satterthwaite: nu_eff = u_c^4 / sum(u_i^4 / nu_i) (GUM G.2b), u_c^2 = sum u_i^2;
!!   an input of infinite degrees of freedom (a Type B estimate) is given as nu_i <= 0.
!! * Weighted mean of n results x_i with standard uncertainties u_i: weights 1/u_i^2, the
!!   internal uncertainty (sum w_i)^(-1/2), chi^2 = sum w_i (x_i - mean)^2 and the Birge
!!   ratio (chi^2/(n - 1))^(1/2) (R. T. Birge, Phys. Rev. 40, 1932).
!! Pure; no state.
module stats
    use kinds, only: dp
    implicit none
    private

    public :: t_cdf, t_quantile, coverage_factor, normal_cdf, normal_quantile
    public :: chi2_sf, welch_satterthwaite, incomplete_beta, gamma_q, weighted_mean
    public :: autocorrelation, rms_about_mean

    !> Degrees of freedom counted as infinite (a coverage factor of the normal distribution).
    real(dp), parameter, public :: NU_INFINITE = 1.0e7_dp

contains

    !> P(T <= t) for Student's t with nu > 0 degrees of freedom (nu >= NU_INFINITE: the
    !! normal distribution).
    pure real(dp) function t_cdf(t, nu) result(p)
        real(dp), intent(in) :: t, nu
        real(dp) :: tail
        if (nu >= NU_INFINITE) then
            p = normal_cdf(t)
            return
        end if
        tail = 0.5_dp*incomplete_beta(nu/(nu + t*t), 0.5_dp*nu, 0.5_dp)
        if (t >= 0.0_dp) then
            p = 1.0_dp - tail
        else
            p = tail
        end if
    end function t_cdf

    !> The p-quantile of Student's t with nu degrees of freedom, 0 < p < 1.
    pure real(dp) function t_quantile(p, nu) result(t)
        real(dp), intent(in) :: p, nu
        real(dp) :: lo, hi, q, f, dens, tn
        integer :: it
        if (nu >= NU_INFINITE) then
            t = normal_quantile(p)
            return
        end if
        q = max(p, 1.0_dp - p)
        lo = 0.0_dp
        hi = 1.0_dp
        do while (t_cdf(hi, nu) < q .and. hi < 1.0e12_dp)
            hi = 2.0_dp*hi
        end do
        do it = 1, 200
            t = 0.5_dp*(lo + hi)
            if (t_cdf(t, nu) < q) then
                lo = t
            else
                hi = t
            end if
            if (hi - lo <= 1.0e-6_dp*hi) exit
        end do
        t = 0.5_dp*(lo + hi)
        ! Newton on the density to the last bits
        do it = 1, 4
            f = t_cdf(t, nu) - q
            dens = exp(log_gamma(0.5_dp*(nu + 1.0_dp)) - log_gamma(0.5_dp*nu) - &
                       0.5_dp*log(nu*acos(-1.0_dp)) - 0.5_dp*(nu + 1.0_dp)*log(1.0_dp + t*t/nu))
            if (.not. (dens > 0.0_dp)) exit
            tn = t - f/dens
            if (.not. (tn > lo .and. tn < hi)) exit
            t = tn
        end do
        if (p < 0.5_dp) t = -t
    end function t_quantile

    !> The coverage factor k of a level of confidence `level` (e.g. 0.95) for nu effective
    !! degrees of freedom: the (1 + level)/2 quantile of Student's t.
    pure real(dp) function coverage_factor(nu, level) result(k)
        real(dp), intent(in) :: nu, level
        k = t_quantile(0.5_dp*(1.0_dp + level), max(nu, 1.0_dp))
    end function coverage_factor

    !> P(Z <= z) for the standard normal distribution.
    pure real(dp) function normal_cdf(z) result(p)
        real(dp), intent(in) :: z
        p = 0.5_dp*erfc(-z/sqrt(2.0_dp))
    end function normal_cdf

    !> The p-quantile of the standard normal distribution, 0 < p < 1.
    pure real(dp) function normal_quantile(p) result(z)
        real(dp), intent(in) :: p
        real(dp) :: lo, hi, f, dens, zn
        integer :: it
        lo = -40.0_dp
        hi = 40.0_dp
        do it = 1, 200
            z = 0.5_dp*(lo + hi)
            if (normal_cdf(z) < p) then
                lo = z
            else
                hi = z
            end if
            if (hi - lo <= 1.0e-7_dp) exit
        end do
        z = 0.5_dp*(lo + hi)
        do it = 1, 4
            f = normal_cdf(z) - p
            dens = exp(-0.5_dp*z*z)/sqrt(2.0_dp*acos(-1.0_dp))
            if (.not. (dens > 0.0_dp)) exit
            zn = z - f/dens
            if (.not. (zn > lo .and. zn < hi)) exit
            z = zn
        end do
    end function normal_quantile

    !> The regularized incomplete beta function I_x(a, b), 0 <= x <= 1, a, b > 0: by the
    !! continued fraction where it converges fast (x < (a + 1)/(a + b + 2)), else by the
    !! symmetry I_x(a, b) = 1 - I_(1-x)(b, a).
    pure recursive real(dp) function incomplete_beta(x, a, b) result(v)
        real(dp), intent(in) :: x, a, b
        real(dp) :: front
        if (x <= 0.0_dp) then
            v = 0.0_dp
            return
        end if
        if (x >= 1.0_dp) then
            v = 1.0_dp
            return
        end if
        if (x > (a + 1.0_dp)/(a + b + 2.0_dp)) then
            v = 1.0_dp - incomplete_beta(1.0_dp - x, b, a)
            return
        end if
        front = exp(log_gamma(a + b) - log_gamma(a) - log_gamma(b) + a*log(x) + &
                    b*log(1.0_dp - x))/a
        v = front*beta_fraction(x, a, b)
    end function incomplete_beta

    !> The continued fraction 1/(1 + d1/(1 + d2/(1 + ...))) of I_x(a, b) (A&S 26.5.8),
    !! d_{2m+1} = -(a + m)(a + b + m) x/((a + 2m)(a + 2m + 1)),
    !! d_{2m} = m (b - m) x/((a + 2m - 1)(a + 2m)), by the modified Lentz method.
    pure real(dp) function beta_fraction(x, a, b) result(f)
        real(dp), intent(in) :: x, a, b
        real(dp), parameter :: TINY_ = 1.0e-300_dp, EPS = 1.0e-15_dp
        real(dp) :: c, d, del, dm
        integer :: m, k
        f = TINY_
        c = f
        d = 0.0_dp
        do k = 0, 2000
            if (k == 0) then
                dm = 1.0_dp
            else if (mod(k, 2) == 1) then
                m = (k - 1)/2
                dm = -(a + m)*(a + b + m)*x/((a + 2*m)*(a + 2*m + 1.0_dp))
            else
                m = k/2
                dm = m*(b - m)*x/((a + 2*m - 1.0_dp)*(a + 2*m))
            end if
            d = 1.0_dp + dm*d
            if (abs(d) < TINY_) d = TINY_
            d = 1.0_dp/d
            c = 1.0_dp + dm/c
            if (abs(c) < TINY_) c = TINY_
            del = c*d
            if (k == 0) then
                f = d      ! the fraction starts 1/(1 + d1/...): its first term is 1
            else
                f = f*del
            end if
            if (k > 0 .and. abs(del - 1.0_dp) < EPS) exit
        end do
    end function beta_fraction

    !> Q(a, x) = Gamma(a, x)/Gamma(a), the regularized upper incomplete gamma function.
    pure real(dp) function gamma_q(a, x) result(q)
        real(dp), intent(in) :: a, x
        real(dp), parameter :: EPS = 1.0e-15_dp, TINY_ = 1.0e-300_dp
        real(dp) :: term, total, ap, b, c, d, del, an, lead
        integer :: n
        if (x <= 0.0_dp) then
            q = 1.0_dp
            return
        end if
        lead = exp(-x + a*log(x) - log_gamma(a))
        if (x < a + 1.0_dp) then
            ! P(a, x) by its series x^a e^-x / Gamma(a+1) sum x^n / ((a+1)...(a+n))
            ap = a
            term = 1.0_dp/a
            total = term
            do n = 1, 10000
                ap = ap + 1.0_dp
                term = term*x/ap
                total = total + term
                if (abs(term) < abs(total)*EPS) exit
            end do
            q = 1.0_dp - total*lead
        else
            ! Q(a, x) by its continued fraction (modified Lentz)
            b = x + 1.0_dp - a
            c = 1.0_dp/TINY_
            d = 1.0_dp/b
            total = d
            do n = 1, 10000
                an = -n*(n - a)
                b = b + 2.0_dp
                d = an*d + b
                if (abs(d) < TINY_) d = TINY_
                c = b + an/c
                if (abs(c) < TINY_) c = TINY_
                d = 1.0_dp/d
                del = d*c
                total = total*del
                if (abs(del - 1.0_dp) < EPS) exit
            end do
            q = total*lead
        end if
        q = max(0.0_dp, min(1.0_dp, q))
    end function gamma_q

    !> P(X > x) for the chi-square distribution with k > 0 degrees of freedom.
    pure real(dp) function chi2_sf(x, k) result(p)
        real(dp), intent(in) :: x, k
        p = gamma_q(0.5_dp*k, 0.5_dp*max(x, 0.0_dp))
    end function chi2_sf

    !> Welch-Satterthwaite's effective degrees of freedom of u_c^2 = sum u_i^2 (nu_i <= 0 or
    !! >= NU_INFINITE: infinite); NU_INFINITE when every term is infinite or u_c = 0.
    pure real(dp) function welch_satterthwaite(u, nu) result(nu_eff)
        real(dp), intent(in) :: u(:), nu(:)
        real(dp) :: uc2, den
        integer :: i
        uc2 = sum(u**2)
        den = 0.0_dp
        do i = 1, size(u)
            if (nu(i) > 0.0_dp .and. nu(i) < NU_INFINITE) den = den + u(i)**4/nu(i)
        end do
        if (den > 0.0_dp .and. uc2 > 0.0_dp) then
            nu_eff = min(NU_INFINITE, uc2**2/den)
        else
            nu_eff = NU_INFINITE
        end if
    end function welch_satterthwaite

    !> The weighted mean of x with standard uncertainties u (each > 0): the mean, its internal
    !! uncertainty (sum w)^(-1/2), chi^2 about the mean and the Birge ratio
    !! (chi^2/(n - 1))^(1/2) (1 for n = 1).
    pure subroutine weighted_mean(x, u, mean, u_int, chi2, birge)
        real(dp), intent(in) :: x(:), u(:)
        real(dp), intent(out) :: mean, u_int, chi2, birge
        real(dp) :: w(size(x))
        w = 1.0_dp/u**2
        mean = sum(w*x)/sum(w)
        u_int = 1.0_dp/sqrt(sum(w))
        chi2 = sum(w*(x - mean)**2)
        birge = 1.0_dp
        if (size(x) > 1) birge = sqrt(chi2/(size(x) - 1))
    end subroutine weighted_mean

    !> The sample autocorrelation of x at a lag of `lag` samples,
    !! sum (x_i - m)(x_(i+lag) - m) / sum (x_i - m)^2 (m the mean); 0 for a constant x or a
    !! lag outside 1 .. n - 1.
    pure real(dp) function autocorrelation(x, lag) result(rho)
        real(dp), intent(in) :: x(:)
        integer, intent(in) :: lag
        real(dp) :: d(size(x)), s0
        integer :: n
        n = size(x)
        rho = 0.0_dp
        if (lag < 1 .or. lag >= n) return
        d = x - sum(x)/n
        s0 = sum(d**2)
        if (s0 <= 0.0_dp) return
        rho = sum(d(1:n - lag)*d(1 + lag:n))/s0
    end function autocorrelation

    !> The root mean square of x about its mean (0 for no x).
    pure real(dp) function rms_about_mean(x) result(r)
        real(dp), intent(in) :: x(:)
        r = 0.0_dp
        if (size(x) == 0) return
        r = sqrt(sum((x - sum(x)/size(x))**2)/size(x))
    end function rms_about_mean

end module stats
