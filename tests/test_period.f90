!> Tests of the random numbers (module random) and of I1 from measured periods (module
!! period_inversion): published generator sequences, exact recovery of I1, the classical
!! limit, the budget's scaling laws and Monte Carlo against first order.
module test_period
    use, intrinsic :: iso_fortran_env, only: int64
    use kinds, only: dp, pi
    use status, only: status_t, ERR_DECK
    use testing, only: tester_t
    use deck, only: deck_t
    use deck_runs, only: rig_of, accuracy_of, deck_inputs
    use random, only: rng_t, rng_stream, rng_from_word, rng_next, rng_uniform, rng_normal, &
                      splitmix64
    use period_inversion, only: input_u_t, period_fit_t, torsion_period_s, invert_periods, &
                                period_budget, period_monte_carlo, period_mc_sample, &
                                linear_inertia
    use unused_arg, only: unused
    implicit none
    private

    public :: run_period_tests, test_rig

contains

    subroutine run_period_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        call unused(exe)   ! every suite is given the executable; this one needs none
        if (t%want('random: published sequences, moments, streams')) call test_random(t)
        if (t%want('period inversion: I1 back from the exact periods')) call test_exact(t)
        if (t%want('period inversion: the classical formula at small amplitude')) &
            call test_linear_limit(t)
        if (t%want('period inversion: budget sensitivities follow the scaling laws')) &
            call test_budget(t)
        if (t%want('period inversion: Monte Carlo against first order')) call test_mc(t)
        if (t%want('period inversion: refusals')) call test_refusals(t)
    end subroutine run_period_tests

    !> A laboratory rig in SI units: b = b' = 0.4 m, l = l' = 1.2 m, a 3.1 kg body whose mass
    !! centre lies 0.15 m below the midpoint of CD, I1 = 0.05 kg m^2 about the vertical.
    function test_rig() result(d)
        type(deck_t) :: d
        d%path = 'test_rig.nml'
        d%name = 'test_rig'
        d%suspension%b = 0.4_dp
        d%suspension%b_prime = 0.4_dp
        d%suspension%l = 1.2_dp
        d%suspension%l_prime = 1.2_dp
        d%suspension%g = 9.80665_dp
        d%body%mass = 3.1_dp
        d%body%inertia = [0.05_dp, 0.06_dp, 0.03_dp]
        d%body%r = sqrt(0.2_dp**2 + 0.15_dp**2)
        d%body%lambda = atan2(0.15_dp, 0.2_dp)
    end function test_rig

    !> splitmix64 and xoshiro256** against the sequences of their published definitions
    !! (computed independently, in Python, from the authors' descriptions); moments of the
    !! uniform and normal deviates; a stream depends only on (seed, k).
    subroutine test_random(t)
        type(tester_t), intent(inout) :: t
        ! splitmix64 from 1234567: its first five outputs (the authors' test vector)
        integer(int64), parameter :: sm(4) = [6457827717110365317_int64, &
            3203168211198807973_int64, -8629252141511181193_int64, 4593380528125082431_int64]
        ! xoshiro256** seeded by splitmix64 from 0: first five outputs, as signed 64-bit
        integer(int64), parameter :: xo(5) = [-7355399402456485196_int64, &
            -4652746763540216534_int64, 1900383378846508768_int64, 7684712102626143532_int64, &
            -4925340083591827879_int64]
        type(rng_t) :: g, h
        integer(int64) :: r
        integer :: k, n
        real(dp) :: u, s1, s2, z, m3
        logical :: ok
        g = rng_from_word(1234567_int64)
        call t%check('random: splitmix64 seeding gives the published sequence', all(g%s == sm))
        call t%check('random: splitmix64 first output', splitmix64(1234567_int64) == sm(1))
        g = rng_from_word(0_int64)
        ok = .true.
        do k = 1, 5
            call rng_next(g, r)
            ok = ok .and. r == xo(k)
        end do
        call t%check('random: xoshiro256** gives the published sequence', ok)
        ! moments: uniform mean 1/2, variance 1/12; normal mean 0, variance 1, skew 0
        n = 200000
        g = rng_stream(42, 7)
        s1 = 0.0_dp
        s2 = 0.0_dp
        ok = .true.
        do k = 1, n
            u = rng_uniform(g)
            ok = ok .and. u > 0.0_dp .and. u <= 1.0_dp
            s1 = s1 + u
            s2 = s2 + (u - 0.5_dp)**2
        end do
        call t%check('random: uniform deviates lie in (0, 1]', ok)
        call t%check_close('random: uniform mean', s1/n, 0.5_dp, atol=5.0_dp*sqrt(1.0_dp/(12*n)))
        call t%check_close('random: uniform variance', s2/n, 1.0_dp/12, rtol=0.02_dp)
        s1 = 0.0_dp
        s2 = 0.0_dp
        m3 = 0.0_dp
        do k = 1, n
            z = rng_normal(g)
            s1 = s1 + z
            s2 = s2 + z*z
            m3 = m3 + z**3
        end do
        call t%check_close('random: normal mean', s1/n, 0.0_dp, atol=5.0_dp/sqrt(real(n, dp)))
        call t%check_close('random: normal variance', s2/n, 1.0_dp, atol=5.0_dp*sqrt(2.0_dp/n))
        call t%check_close('random: normal skewness', m3/n, 0.0_dp, atol=5.0_dp*sqrt(15.0_dp/n))
        ! streams: the same (seed, k) gives the same numbers, neighbours differ
        g = rng_stream(5, 100)
        h = rng_stream(5, 100)
        call t%check('random: a stream is a function of (seed, k)', &
            rng_normal(g) == rng_normal(h))
        g = rng_stream(5, 100)
        h = rng_stream(5, 101)
        call t%check('random: neighbouring streams differ', rng_uniform(g) /= rng_uniform(h))
        g = rng_stream(5, 100)
        h = rng_stream(6, 100)
        call t%check('random: neighbouring seeds differ', rng_uniform(g) /= rng_uniform(h))
    end subroutine test_random

    !> Periods made by the exact torsion at three amplitudes give back I1 to 1e-8, from a
    !! start 30 % off, with no residual.
    subroutine test_exact(t)
        type(tester_t), intent(inout) :: t
        type(deck_t) :: d
        type(period_fit_t) :: f
        type(status_t) :: st
        type(input_u_t) :: u
        real(dp) :: amps(3), periods(3)
        integer :: k
        d = test_rig()
        amps = [10.0_dp, 30.0_dp, 60.0_dp]
        do k = 1, 3
            call torsion_period_s(rig_of(d), 0.05_dp, amps(k), periods(k), st)
        end do
        call t%check('exact: periods of the test rig', st%code == 0)
        call t%check('exact: the period grows with the amplitude', &
            periods(1) < periods(2) .and. periods(2) < periods(3))
        d%body%inertia(1) = 0.065_dp
        u%period = 1.0e-4_dp
        call invert_periods(rig_of(d), accuracy_of(d), periods, amps, u, f, st)
        call t%check('exact: inversion succeeds', st%code == 0)
        call t%check_close('exact: I1 from three exact periods', f%i1, 0.05_dp, rtol=1.0e-8_dp)
        call t%check('exact: residual below 1e-12 s', f%residual_rms < 1.0e-12_dp)
        call t%check('exact: few Gauss-Newton iterations', f%iterations <= 12)
        d%body%inertia(1) = 0.035_dp
        call invert_periods(rig_of(d), accuracy_of(d), periods(3:3), amps(3:3), u, f, st)
        call t%check_close('exact: I1 from one period at 60 deg, start 30% low', f%i1, &
            0.05_dp, rtol=1.0e-8_dp)
    end subroutine test_exact

    !> At small amplitude, the exact inversion tends to I1 = m g b b' T^2 / (16 pi^2 l)
    !! (b = b', equal cables), and the gap shrinks as amplitude^2.
    subroutine test_linear_limit(t)
        type(tester_t), intent(inout) :: t
        type(deck_t) :: d
        type(status_t) :: st
        real(dp) :: tp, e(2)
        integer :: k
        d = test_rig()
        do k = 1, 2
            call torsion_period_s(rig_of(d), 0.05_dp, 2.0_dp/k, tp, st)
            e(k) = linear_inertia(rig_of(d), tp)/0.05_dp - 1.0_dp
        end do
        call t%check('linear limit: periods computed', st%code == 0)
        call t%check('linear limit: within 2e-4 at 1 degree', abs(e(2)) < 2.0e-4_dp)
        call t%check_close('linear limit: the gap falls as amplitude^2', e(1)/e(2), 4.0_dp, &
            rtol=0.01_dp)
        call t%check('linear limit: the linear formula overestimates', e(1) > 0.0_dp)
    end subroutine test_linear_limit

    !> Sensitivities at small amplitude follow I1 ~ m g b b' T^2 / l: c_m = I1/m (exact at any
    !! amplitude), c_g = I1/g, c_b = I1/b, c_b' = I1/b', c_T = 2 I1/T, c_l = c_l' =
    !! -I1/(2 l) (each cable half of the common length), c_A = 0 at the small-amplitude limit.
    subroutine test_budget(t)
        type(tester_t), intent(inout) :: t
        type(deck_t) :: d
        type(period_fit_t) :: f
        type(status_t) :: st
        type(input_u_t) :: u
        real(dp) :: tp(1), a(1), i1, uu
        d = test_rig()
        a = 0.5_dp
        call torsion_period_s(rig_of(d), 0.05_dp, a(1), tp(1), st)
        u = input_u_t(mass=0.001_dp, l=0.001_dp, l_prime=0.001_dp, b=0.0005_dp, &
                      b_prime=0.0005_dp, g=0.001_dp, period=1.0e-4_dp, amplitude=0.5_dp)
        call invert_periods(rig_of(d), accuracy_of(d), tp, a, u, f, st)
        call period_budget(rig_of(d), accuracy_of(d), tp, a, u, f, st)
        call t%check('budget: computed', st%code == 0)
        if (st%code /= 0) return
        i1 = f%i1
        call t%check('budget: 8 rows for one period', size(f%budget) == 8)
        call t%check_close('budget: c_mass = I1/m (exact)', f%budget(1)%sensitivity, &
            i1/d%body%mass, rtol=1.0e-6_dp)
        ! I1 ~ g only up to the body's vertical kinetic energy (z'^2 next to I1 in J of the
        ! energy integral), 1e-5 of I1 at 0.5 deg
        call t%check_close('budget: c_g = I1/g', f%budget(6)%sensitivity, i1/d%suspension%g, &
            rtol=2.0e-5_dp)
        call t%check_close('budget: c_l = -I1/(2l)', f%budget(2)%sensitivity, &
            -i1/(2*d%suspension%l), rtol=2.0e-3_dp)
        call t%check_close('budget: c_l_prime = c_l', f%budget(3)%sensitivity, &
            f%budget(2)%sensitivity, rtol=1.0e-9_dp)
        call t%check_close('budget: c_b = I1/b', f%budget(4)%sensitivity, i1/d%suspension%b, &
            rtol=2.0e-3_dp)
        call t%check_close('budget: c_b_prime = I1/b''', f%budget(5)%sensitivity, &
            i1/d%suspension%b_prime, rtol=2.0e-3_dp)
        call t%check_close('budget: c_T = 2 I1/T', f%budget(7)%sensitivity, 2*i1/tp(1), &
            rtol=1.0e-4_dp)
        call t%check('budget: amplitude matters little at 0.5 deg', &
            abs(f%budget(8)%sensitivity)*1.0_dp < 1.0e-4_dp*i1)
        uu = sqrt((i1/d%body%mass*u%mass)**2 + 2*(i1/(2*d%suspension%l)*u%l)**2 + &
                  (i1/d%suspension%b*u%b)**2 + &
                  (i1/d%suspension%b_prime*u%b_prime)**2 + (2*i1/tp(1)*u%period)**2 + &
                  (i1/d%suspension%g*u%g)**2)
        call t%check_close('budget: u(I1) = the root sum of squares of the laws', f%u_i1, uu, &
            rtol=3.0e-3_dp)
        call t%check('budget: contributions are |c| u', &
            all(abs(f%budget%contribution - abs(f%budget%sensitivity)*f%budget%u) <= &
                1.0e-15_dp*i1))
    end subroutine test_budget

    !> Monte Carlo: 2000 samples agree with the first-order u within 3 standard errors of a
    !! standard deviation (sqrt(2/n) relative); samples do not depend on order or threads.
    subroutine test_mc(t)
        type(tester_t), intent(inout) :: t
        type(deck_t) :: d
        type(period_fit_t) :: f
        type(status_t) :: st
        type(input_u_t) :: u
        real(dp) :: tp(2), a(2), mean, sdev, s1, s2
        integer, parameter :: n = 2000
        d = test_rig()
        a = [15.0_dp, 40.0_dp]
        call torsion_period_s(rig_of(d), 0.05_dp, a(1), tp(1), st)
        call torsion_period_s(rig_of(d), 0.05_dp, a(2), tp(2), st)
        u = input_u_t(mass=0.001_dp, l=0.001_dp, l_prime=0.001_dp, b=0.0005_dp, &
                      b_prime=0.0005_dp, g=0.0_dp, period=1.0e-4_dp, amplitude=0.5_dp)
        call invert_periods(rig_of(d), accuracy_of(d), tp, a, u, f, st)
        call period_budget(rig_of(d), accuracy_of(d), tp, a, u, f, st)
        call period_monte_carlo(d, rig_of(d), accuracy_of(d), deck_inputs(d, .false.), tp, a, u, &
                                f%i1, n, 2026, mean, sdev, st)
        call t%check('monte carlo: runs', st%code == 0)
        call t%check_close('monte carlo: u agrees with first order', sdev, f%u_i1, &
            rtol=3.0_dp*sqrt(2.0_dp/n))
        call t%check_close('monte carlo: mean agrees with the estimate', mean, f%i1, &
            atol=4.0_dp*f%u_i1/sqrt(real(n, dp)))
        call period_mc_sample(rig_of(d), accuracy_of(d), tp, a, u, f%i1, 2026, 17, s1, st)
        call period_mc_sample(rig_of(d), accuracy_of(d), tp, a, u, f%i1, 2026, 17, s2, st)
        call t%check('monte carlo: a sample depends only on (seed, k)', s1 == s2)
    end subroutine test_mc

    !> A period no positive I1 gives, and a symmetric rig whose b1 is not vertical, are
    !! refused with ERR_DECK naming the variable (unequal cables are inverted by simulation:
    !! test_identify).
    subroutine test_refusals(t)
        type(tester_t), intent(inout) :: t
        type(deck_t) :: d
        type(period_fit_t) :: f
        type(status_t) :: st
        type(input_u_t) :: u
        d = test_rig()
        call invert_periods(rig_of(d), accuracy_of(d), [0.05_dp], [20.0_dp], u, f, st)
        call t%check('refusal: a period shorter than T(I1 -> 0) is ERR_DECK', st%code == ERR_DECK)
        if (st%code /= 0) call t%check('refusal: message names periods(1) and says why', &
            index(st%msg, 'periods(1)') > 0 .and. index(st%msg, 'no positive I1') > 0)
        ! b1 horizontal at rest (btilde's rows a cyclic permutation): torsion turns the
        ! body about b3, its period does not depend on I1
        d = test_rig()
        d%body%btilde = reshape([0.0_dp, 0.0_dp, 1.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, &
                            0.0_dp], [3, 3])
        call invert_periods(rig_of(d), accuracy_of(d), [1.5_dp], [20.0_dp], u, f, st)
        call t%check('refusal: b1 not vertical at rest is ERR_DECK', st%code == ERR_DECK)
        if (st%code /= 0) call t%check('refusal: message says b1 is not vertical', &
            index(st%msg, 'b1 is not vertical') > 0)
    end subroutine test_refusals

end module test_period
