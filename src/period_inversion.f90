!> The moment of inertia I1 from measured periods of torsion, with its uncertainty.
!!
!! The bifilar rig exists to measure moments of inertia: a period of torsional oscillation
!! is measured and turned into I1, the principal moment about b1, vertical at rest.  The
!! classical formula I1 = m g b b' T^2 / (16 pi^2 l) comes from the linearised equations;
!! here the period is the exact period of pure torsion (eqs. (45)-(49), module floquet's
!! torsion_period: the energy integral of the one-degree-of-freedom motion, for b /= b'
!! too), so amplitude does not bias the result.
!!
!! * Inversion: several periods T_i measured at peak amplitudes A_i (degrees of theta4) are
!!   combined by weighted least squares, min sum w_i (T_i(I1) - T_i^meas)^2, with
!!   w_i = 1/(u_T^2 + (dT_i/dA u_A)^2) (equal weights when no uncertainty is given), solved
!!   by Gauss-Newton in the one unknown, safeguarded to stay at I1 > 0.  T(I1) increases
!!   strictly with I1 and tends to a positive limit T_min as I1 -> 0 (the body still rises
!!   as it turns), so a period below T_min is refused: no positive I1 gives it.
!! * First-order uncertainty (GUM, JCGM 100:2008, section 5.1): u(I1)^2 = sum_j (c_j u_j)^2
!!   over the independent inputs (mass, l, l', b, b', g, each period, each amplitude), with
!!   the sensitivities c_j = dI1/dx_j by central differences of the whole inversion.  Pure
!!   torsion needs l = l'; the rig is then mirror-symmetric, T(l, l') = T(l', l), so to
!!   first order dI1/dl = dI1/dl' = (1/2) dI1/dL with L the common length.  A change of b'
!!   moves the two body attachment points symmetrically: the mass centre keeps its depth
!!   below, and its offset along, the midpoint of CD (r and lambda follow).
!! * Monte Carlo (GUM Supplement 1, JCGM 101:2008): sample k draws every input from its
!!   normal distribution with the k-th stream of the seed (module random) and inverts again;
!!   u is the standard deviation of the samples.  The two cable lengths are drawn
!!   independently and the period taken at their mean (their difference changes the period
!!   only at second order).  Each sample depends only on (seed, k): any order, thread or
!!   rank gives the same numbers.
!!
!! Units are the deck's (consistent units, time in seconds): I1 in mass x length^2,
!! periods in s, amplitudes in degrees.  No routine stops; failures come back in status_t.
module period_inversion
    use kinds, only: dp, pi, deg
    use status, only: status_t, set_error, ERR_DECK, ERR_NUMERIC
    use geometry, only: pendulum_t
    use deck, only: deck_t
    use simulate, only: make_pendulum
    use floquet, only: check_torsion_scene, torsion_period
    use random, only: rng_t, rng_stream, rng_normal
    implicit none
    private

    !> Standard uncertainties of the inputs (deck units; period in s, amplitude in degrees);
    !! each >= 0, 0 when not known.
    type, public :: input_u_t
        real(dp) :: mass = 0.0_dp, l = 0.0_dp, l_prime = 0.0_dp, b = 0.0_dp, b_prime = 0.0_dp
        real(dp) :: g = 0.0_dp, period = 0.0_dp, amplitude = 0.0_dp
    end type input_u_t

    !> One line of an uncertainty budget.
    type, public :: budget_row_t
        character(len=24) :: input = ''         !! e.g. mass, l, period(2)
        real(dp) :: value = 0.0_dp              !! the input's value (deck units)
        real(dp) :: u = 0.0_dp                  !! its standard uncertainty
        real(dp) :: sensitivity = 0.0_dp        !! dI1/dx
        real(dp) :: contribution = 0.0_dp       !! |sensitivity| u
    end type budget_row_t

    !> Result of an inversion of periods.
    type, public :: period_fit_t
        real(dp) :: i1 = 0.0_dp                 !! estimate of I1 (deck units)
        real(dp) :: u_i1 = 0.0_dp               !! first-order standard uncertainty (budget)
        real(dp) :: residual_rms = 0.0_dp       !! rms of T(I1) - T measured (s)
        integer :: iterations = 0               !! Gauss-Newton iterations
        real(dp), allocatable :: model_periods(:)   !! T_i(I1) (s)
        type(budget_row_t), allocatable :: budget(:)
    end type period_fit_t

    public :: torsion_period_s, invert_periods, period_budget, period_mc_sample
    public :: period_monte_carlo, linear_inertia

    integer, parameter :: MAX_ITER = 60         !! Gauss-Newton iterations
    real(dp), parameter :: I_TOL = 1.0e-14_dp   !! relative change of I1 that ends them
    real(dp), parameter :: FD_REL = 1.0e-6_dp   !! relative step of the sensitivities
    real(dp), parameter :: I_TINY = 1.0e-9_dp   !! I1 -> 0 limit, over m b'^2

contains

    !> The exact period (s) of pure torsion of the deck's rig with I1 = i1 at peak
    !! amplitude amp_deg.  ERR_DECK when the rig is not a torsion scene (equal cables, mass
    !! centre below the midpoint of CD, b1 vertical at rest) or the cables cannot reach.
    subroutine torsion_period_s(d, i1, amp_deg, t, stat)
        type(deck_t), intent(in) :: d           !! the rig (deck units)
        real(dp), intent(in) :: i1              !! principal moment about b1 (deck units)
        real(dp), intent(in) :: amp_deg         !! peak amplitude of theta4 (degrees)
        real(dp), intent(out) :: t              !! period (s)
        type(status_t), intent(out) :: stat
        type(pendulum_t) :: p
        call torsion_pendulum(d, i1, p, stat)
        t = 0.0_dp
        if (stat%code /= 0) return
        call scaled_period(d, p, amp_deg, t, stat)
    end subroutine torsion_period_s

    !> Scaled parameters of the rig with I1 = i1, checked to be a torsion scene with b1
    !! vertical at rest.
    subroutine torsion_pendulum(d, i1, p, stat)
        type(deck_t), intent(in) :: d
        real(dp), intent(in) :: i1
        type(pendulum_t), intent(out) :: p
        type(status_t), intent(out) :: stat
        type(deck_t) :: dd
        integer :: ivert
        dd = d
        dd%inertia(1) = i1
        call make_pendulum(dd, p, stat)
        if (stat%code /= 0) return
        call check_torsion_scene(p, ivert, stat)
        if (stat%code /= 0) return
        if (ivert /= 1) call set_error(stat, ERR_DECK, '&body btilde: b1 is not vertical at '// &
            'rest (row 1 must be (+-1, 0, 0)): the period of torsion does not depend on I1')
    end subroutine torsion_pendulum

    !> Period in seconds of the scaled pendulum p (period in tau over sqrt(g/b')).
    subroutine scaled_period(d, p, amp_deg, t, stat)
        type(deck_t), intent(in) :: d
        type(pendulum_t), intent(in) :: p
        real(dp), intent(in) :: amp_deg
        real(dp), intent(out) :: t
        type(status_t), intent(out) :: stat
        call torsion_period(p, amp_deg*deg, 1, t, stat)
        t = t*sqrt(d%b_prime/d%g)
    end subroutine scaled_period

    !> I1 by weighted least squares from periods (s) measured at peak amplitudes (degrees).
    !! Starts from d%inertia(1).  ERR_DECK for a period no positive I1 can give (or not a
    !! torsion scene); ERR_NUMERIC when Gauss-Newton does not converge.
    subroutine invert_periods(d, periods, amps, u, fit, stat)
        type(deck_t), intent(in) :: d           !! the rig; inertia(1) is the start guess
        real(dp), intent(in) :: periods(:)      !! measured full periods (s)
        real(dp), intent(in) :: amps(:)         !! their peak amplitudes (degrees)
        type(input_u_t), intent(in) :: u        !! uncertainties (weights from period, amplitude)
        type(period_fit_t), intent(out) :: fit
        type(status_t), intent(out) :: stat
        real(dp) :: w(size(periods)), tm(size(periods)), g(size(periods)), r(size(periods))
        real(dp) :: scale, i1, di, s0, s1, ilo, tmin, ta, tb, h
        integer :: i, it, half
        character(len=300) :: buf
        stat%code = 0
        allocate (fit%model_periods(size(periods)))
        fit%model_periods = 0.0_dp
        if (size(periods) < 1 .or. size(amps) /= size(periods)) then
            call set_error(stat, ERR_DECK, '&measurement periods, amplitudes: need one '// &
                'amplitude per period and at least one period')
            return
        end if
        scale = d%mass*d%b_prime**2
        ilo = I_TINY*scale
        ! feasibility: T(I1) > T(0+) for every period; weights from the amplitudes' effect
        do i = 1, size(periods)
            call torsion_period_s(d, ilo, amps(i), tmin, stat)
            if (stat%code /= 0) return
            if (.not. (periods(i) > tmin)) then
                write (buf, '(a,i0,a,es12.5,a,es12.5,a,f0.3,a)') '&measurement periods(', i, &
                    ') = ', periods(i), ' s: shorter than the period of this rig with I1 -> 0 (', &
                    tmin, ' s at ', amps(i), ' deg); no positive I1 gives it: check the '// &
                    'units (s), the amplitude and the suspension lengths'
                call set_error(stat, ERR_DECK, trim(buf))
                return
            end if
        end do
        i1 = d%inertia(1)
        if (.not. (i1 > ilo)) i1 = scale
        w = 1.0_dp
        if (u%period > 0.0_dp .or. u%amplitude > 0.0_dp) then
            do i = 1, size(periods)
                h = 1.0e-4_dp*max(1.0_dp, amps(i))
                call torsion_period_s(d, i1, amps(i) + h, ta, stat)
                if (stat%code == 0) call torsion_period_s(d, i1, amps(i) - h, tb, stat)
                if (stat%code /= 0) return
                w(i) = 1.0_dp/(u%period**2 + ((ta - tb)/(2*h)*u%amplitude)**2)
            end do
        end if
        call residuals(i1, tm, r, s0, stat)
        if (stat%code /= 0) return
        do it = 1, MAX_ITER
            fit%iterations = it
            call slopes(i1, tm, g, stat)
            if (stat%code /= 0) return
            di = -sum(w*g*r)/sum(w*g*g)
            ! keep I1 positive and make the weighted sum of squares fall (step halving)
            do half = 0, 60
                if (i1 + di > ilo) then
                    call residuals(i1 + di, tm, r, s1, stat)
                    if (stat%code /= 0) return
                    if (s1 <= s0) exit
                end if
                di = 0.5_dp*di
            end do
            if (half > 60) exit
            i1 = i1 + di
            s0 = s1
            if (abs(di) <= I_TOL*i1) then
                fit%i1 = i1
                fit%model_periods = tm
                fit%residual_rms = sqrt(sum((tm - periods)**2)/size(periods))
                return
            end if
        end do
        write (buf, '(a,i0,a,es12.5)') 'period inversion: Gauss-Newton did not converge in ', &
            fit%iterations, ' iterations (I1 = ', i1
        call set_error(stat, ERR_NUMERIC, trim(buf)//'); check that the periods agree with '// &
            'each other and with the rig')
    contains
        subroutine residuals(ii, tmod, rr, ss, st)
            real(dp), intent(in) :: ii
            real(dp), intent(out) :: tmod(:), rr(:), ss
            type(status_t), intent(out) :: st
            integer :: k
            do k = 1, size(periods)
                call torsion_period_s(d, ii, amps(k), tmod(k), st)
                if (st%code /= 0) return
            end do
            rr = tmod - periods
            ss = sum(w*rr*rr)
        end subroutine residuals
        subroutine slopes(ii, tmod, gg, st)
            real(dp), intent(in) :: ii, tmod(:)
            real(dp), intent(out) :: gg(:)
            type(status_t), intent(out) :: st
            real(dp) :: tp, hh
            integer :: k
            ! forward difference: only the direction of the step depends on it
            hh = 1.0e-7_dp*ii
            do k = 1, size(periods)
                call torsion_period_s(d, ii + hh, amps(k), tp, st)
                if (st%code /= 0) return
                gg(k) = (tp - tmod(k))/hh
            end do
        end subroutine slopes
    end subroutine invert_periods

    !> First-order (GUM) budget of an inversion: fills fit%budget (mass, l, l_prime, b,
    !! b_prime, g, then period(i) and amplitude(i) for each period) and fit%u_i1.  The
    !! sensitivities are central differences of the whole inversion (relative step 1e-6).
    subroutine period_budget(d, periods, amps, u, fit, stat)
        type(deck_t), intent(in) :: d           !! the rig
        real(dp), intent(in) :: periods(:)      !! measured periods (s)
        real(dp), intent(in) :: amps(:)         !! their amplitudes (degrees)
        type(input_u_t), intent(in) :: u        !! standard uncertainties
        type(period_fit_t), intent(inout) :: fit    !! from invert_periods
        type(status_t), intent(out) :: stat
        integer :: n, k, i
        real(dp) :: c, hx
        character(len=24) :: nm
        n = size(periods)
        if (allocated(fit%budget)) deallocate (fit%budget)
        allocate (fit%budget(6 + 2*n))
        stat%code = 0
        do k = 1, 6 + 2*n
            select case (k)
            case (1)
                call row('mass', d%mass, u%mass)
            case (2)
                call row('l', d%l, u%l)
            case (3)
                call row('l_prime', d%l_prime, u%l_prime)
            case (4)
                call row('b', d%b, u%b)
            case (5)
                call row('b_prime', d%b_prime, u%b_prime)
            case (6)
                call row('g', d%g, u%g)
            case default
                i = k - 6
                if (i <= n) then
                    write (nm, '(a,i0,a)') 'period(', i, ')'
                    call row(nm, periods(i), u%period)
                else
                    write (nm, '(a,i0,a)') 'amplitude(', i - n, ')'
                    call row(nm, amps(i - n), u%amplitude)
                end if
            end select
            if (stat%code /= 0) return
        end do
        fit%u_i1 = sqrt(sum(fit%budget%contribution**2))
    contains
        subroutine row(name, x, ux)
            character(len=*), intent(in) :: name
            real(dp), intent(in) :: x, ux
            real(dp) :: ip, im
            hx = FD_REL*max(abs(x), tiny(1.0_dp))
            call inverted(name, x + hx, ip, stat)
            if (stat%code == 0) call inverted(name, x - hx, im, stat)
            if (stat%code /= 0) then
                stat%msg = 'uncertainty budget, input '//trim(name)//': '//stat%msg
                return
            end if
            c = (ip - im)/(2*hx)
            fit%budget(k) = budget_row_t(name, x, ux, c, abs(c)*ux)
        end subroutine row
        !> I1 with one input (by budget name) set to value v.
        subroutine inverted(name, v, i1, st)
            character(len=*), intent(in) :: name
            real(dp), intent(in) :: v
            real(dp), intent(out) :: i1
            type(status_t), intent(out) :: st
            type(deck_t) :: dd
            type(period_fit_t) :: f2
            real(dp) :: pp(n), aa(n)
            dd = d
            dd%inertia(1) = fit%i1
            pp = periods
            aa = amps
            select case (name)
            case ('mass')
                dd%mass = v
            case ('l', 'l_prime')
                ! mirror symmetry: each cable carries half the effect of the common length
                dd%l = d%l + 0.5_dp*(v - x_of(name))
                dd%l_prime = d%l_prime + 0.5_dp*(v - x_of(name))
            case ('b')
                dd%b = v
            case ('b_prime')
                call move_b_prime(dd, v)
            case ('g')
                dd%g = v
            case default
                if (name(1:6) == 'period') then
                    pp(k - 6) = v
                else
                    aa(k - 6 - n) = v
                end if
            end select
            call invert_periods(dd, pp, aa, u, f2, st)
            i1 = f2%i1
        end subroutine inverted
        pure real(dp) function x_of(name)
            character(len=*), intent(in) :: name
            if (name == 'l') then
                x_of = d%l
            else
                x_of = d%l_prime
            end if
        end function x_of
    end subroutine period_budget

    !> Set b' to v moving both body attachment points symmetrically: the mass centre keeps
    !! its depth r sin(lambda) below CD and its offset r cos(lambda) - b'/2 from the
    !! midpoint of CD.
    pure subroutine move_b_prime(d, v)
        type(deck_t), intent(inout) :: d        !! rig to change
        real(dp), intent(in) :: v               !! new b'
        real(dp) :: depth, along
        depth = d%r*sin(d%lambda)
        along = d%r*cos(d%lambda) - 0.5_dp*d%b_prime + 0.5_dp*v
        d%b_prime = v
        d%r = sqrt(depth**2 + along**2)
        d%lambda = atan2(depth, along)
    end subroutine move_b_prime

    !> Monte Carlo sample k: every input drawn from N(value, u^2) with stream k of `seed`
    !! (draw order: mass, l, l_prime, b, b_prime, g, then period and amplitude of each
    !! measurement), then the inversion again; i1 is that sample's I1.
    subroutine period_mc_sample(d, periods, amps, u, i1_start, seed, k, i1, stat)
        type(deck_t), intent(in) :: d           !! the rig
        real(dp), intent(in) :: periods(:), amps(:)   !! measurements (s, degrees)
        type(input_u_t), intent(in) :: u        !! standard uncertainties
        real(dp), intent(in) :: i1_start        !! start of the inversion (e.g. the estimate)
        integer, intent(in) :: seed, k          !! seed and sample number
        real(dp), intent(out) :: i1             !! the sample's I1
        type(status_t), intent(out) :: stat
        type(rng_t) :: g
        type(deck_t) :: dd
        type(period_fit_t) :: f
        real(dp) :: pp(size(periods)), aa(size(amps)), la, lb
        integer :: i
        g = rng_stream(seed, k)
        dd = d
        dd%inertia(1) = i1_start
        dd%mass = d%mass + u%mass*rng_normal(g)
        la = d%l + u%l*rng_normal(g)
        lb = d%l_prime + u%l_prime*rng_normal(g)
        dd%l = 0.5_dp*(la + lb)
        dd%l_prime = dd%l
        dd%b = d%b + u%b*rng_normal(g)
        call move_b_prime(dd, d%b_prime + u%b_prime*rng_normal(g))
        dd%g = d%g + u%g*rng_normal(g)
        do i = 1, size(periods)
            pp(i) = periods(i) + u%period*rng_normal(g)
            aa(i) = amps(i) + u%amplitude*rng_normal(g)
        end do
        call invert_periods(dd, pp, aa, u, f, stat)
        i1 = f%i1
        if (stat%code /= 0) then
            stat%msg = 'Monte Carlo sample '//itoa(k)//': '//stat%msg
        end if
    end subroutine period_mc_sample

    !> n Monte Carlo samples (OpenMP over the samples; the result does not depend on the
    !! number of threads): their mean and standard deviation.
    subroutine period_monte_carlo(d, periods, amps, u, i1_start, n, seed, mean, sdev, stat)
        type(deck_t), intent(in) :: d           !! the rig
        real(dp), intent(in) :: periods(:), amps(:)   !! measurements (s, degrees)
        type(input_u_t), intent(in) :: u        !! standard uncertainties
        real(dp), intent(in) :: i1_start        !! start of each inversion
        integer, intent(in) :: n, seed          !! samples (>= 2) and seed
        real(dp), intent(out) :: mean, sdev     !! of the sampled I1
        type(status_t), intent(out) :: stat
        real(dp) :: s(n)
        type(status_t) :: st(n)
        integer :: k
        mean = 0.0_dp
        sdev = 0.0_dp
        stat%code = 0
        if (n < 2) then
            call set_error(stat, ERR_DECK, '&measurement monte_carlo: need at least 2 samples')
            return
        end if
        !$omp parallel do schedule(dynamic, 16) default(shared) private(k)
        do k = 1, n
            call period_mc_sample(d, periods, amps, u, i1_start, seed, k, s(k), st(k))
        end do
        !$omp end parallel do
        do k = 1, n
            if (st(k)%code /= 0) then
                stat = st(k)
                return
            end if
        end do
        mean = sum(s)/n
        sdev = sqrt(sum((s - mean)**2)/(n - 1))
    end subroutine period_monte_carlo

    !> The classical small-amplitude formula I1 = m g b b' T^2 / (16 pi^2 l) (deck units).
    pure real(dp) function linear_inertia(d, t) result(i1)
        type(deck_t), intent(in) :: d           !! the rig
        real(dp), intent(in) :: t               !! period (s)
        i1 = d%mass*d%g*d%b*d%b_prime*t**2/(16.0_dp*pi**2*d%l)
    end function linear_inertia

    pure function itoa(i) result(s)
        integer, intent(in) :: i
        character(len=:), allocatable :: s
        character(len=16) :: buf
        write (buf, '(i0)') i
        s = trim(buf)
    end function itoa

end module period_inversion
