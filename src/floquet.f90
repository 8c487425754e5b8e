!> Floquet stability of pure torsion, Kane & Tseng (1966) eqs. (45)-(51).
!!
!! With equal cables, the mass centre on the vertical bisector of AB and a principal axis
!! vertical, pure torsion is an exact periodic motion.  Its period t* comes from the energy
!! integral of the one-degree-of-freedom motion (eqs. (45)-(48), generalised to b /= b'):
!!     t* = 4 int_0^A sqrt(J(q) / (2 (z(A) - z(q)))) dq,   J = I_v + z'(q)^2,
!! with z(q) the height of the body as it turns by q and I_v its vertical moment of inertia,
!! evaluated by Gauss-Legendre quadrature after q = A sin(phi), which removes the endpoint
!! singularity.  The variational equations (51), dH/dt = Z H, are integrated along the orbit
!! in the regular chart of bifilar_model (the orbit lies on theta2 = 0, where the paper's
!! coordinates are singular) over `nseg` shooting segments; the multipliers are the
!! eigenvalues of the product of the segment matrices (LAPACK DGEEV).  Z is the Jacobian of
!! the chart right-hand side by Richardson-extrapolated central differences.
module floquet
    use kinds, only: dp, pi
    use status, only: status_t, set_error, ERR_DECK, ERR_NUMERIC
    use ode_system, only: ode_system_t
    use geometry, only: pendulum_t, raised_angles, solve_theta5
    use bifilar_model, only: chart_accelerations, chart_state, NSTATE
    use lsoda, only: lsoda_t, lsoda_stats_t
    use lapack_wrap, only: la_eig
    implicit none
    private

    integer, parameter :: NV = NSTATE + NSTATE*NSTATE   !! orbit + monodromy columns

    !> The orbit and its variational equations as one ODE system.
    type, extends(ode_system_t), public :: variational_t
        type(pendulum_t) :: p
    contains
        procedure :: rhs => variational_rhs
    end type variational_t

    !> Result of one Floquet analysis.
    type, public :: floquet_result_t
        real(dp) :: period = 0.0_dp             !! t* in units of tau
        real(dp) :: max_modulus = 0.0_dp        !! largest |multiplier| among the non-trivial
        logical :: stable = .false.             !! max_modulus <= 1 + stability_margin
        complex(dp) :: multipliers(NSTATE) = (0.0_dp, 0.0_dp)  !! sorted by decreasing modulus
        logical :: trivial(NSTATE) = .false.    !! the four multipliers that are 1 by structure
        real(dp) :: orbit_closure = 0.0_dp      !! |y(t*) - y(0)|, max norm
        integer :: steps = 0, rhs_evaluations = 0
    end type floquet_result_t

    real(dp), parameter, public :: STABILITY_MARGIN = 1.0e-6_dp

    public :: check_torsion_scene, torsion_period, jacobian_z, monodromy, floquet_analysis

contains

    !> Refuse a scene in which pure torsion is not an exact motion, saying which condition
    !! fails: equal cables, mass centre on the vertical bisector of AB, a principal axis
    !! vertical at rest.  Returns the index of the vertical principal axis.
    subroutine check_torsion_scene(p, ivert, stat)
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        integer, intent(out) :: ivert           !! which b_i is vertical at rest
        type(status_t), intent(out) :: stat     !! ERR_DECK naming the failed condition
        integer :: i
        character(len=200) :: buf
        ivert = 0
        if (abs(p%big_l - p%big_lp) > 1.0e-12_dp*p%big_l) then
            write (buf, '(a,es12.5,a,es12.5,a)') '&suspension l/b'' = ', p%big_l, &
                ', l_prime/b'' = ', p%big_lp, ': pure torsion needs equal cables (l = l_prime)'
            call set_error(stat, ERR_DECK, trim(buf))
            return
        end if
        ! at rest R* - C = r (s_lam ntilde1 - c_lam ntilde3) with ntilde1 = -n3, ntilde3 = -n2:
        ! on the vertical through O when r cos(lambda) = b'/2
        if (abs(p%r*cos(p%lambda) - 0.5_dp) > 1.0e-9_dp) then
            write (buf, '(a,es12.5,a)') '&body r cos(lambda) / b'' = ', p%r*cos(p%lambda), &
                ': the mass centre must lie on the vertical bisector of AB (r cos(lambda) = b''/2)'
            call set_error(stat, ERR_DECK, trim(buf))
            return
        end if
        ! b_i vertical at rest: row i of btilde is (+-1, 0, 0) (ntilde1 is vertical at rest)
        do i = 1, 3
            if (abs(abs(p%btilde(i, 1)) - 1.0_dp) < 1.0e-9_dp) ivert = i
        end do
        if (ivert == 0) then
            call set_error(stat, ERR_DECK, '&body btilde: no principal axis is vertical at '// &
                'rest (one row of btilde must be (+-1, 0, 0))')
        end if
    end subroutine check_torsion_scene

    !> Period t* (units of tau) of pure torsion with amplitude `amp` (rad).
    subroutine torsion_period(p, amp, ivert, period, stat)
        type(pendulum_t), intent(in) :: p       !! scaled parameters (a torsion scene)
        real(dp), intent(in) :: amp             !! amplitude of theta4 (rad), 0 < amp < pi
        integer, intent(in) :: ivert            !! vertical principal axis
        real(dp), intent(out) :: period         !! t*
        type(status_t), intent(out) :: stat     !! ERR_DECK when the cables cannot reach
        integer, parameter :: ng = 48
        real(dp) :: x(ng), w(ng), phi, q, zs_q, zs_a, dz, dv, jq, s
        integer :: k
        call gauss_legendre(x, w)
        period = 0.0_dp
        zs_a = p%big_l**2 - h2(amp)
        if (.not. (zs_a > 0.0_dp)) then
            call set_error(stat, ERR_DECK, '&floquet amplitude: the cables cannot reach '// &
                'the raised position at this amplitude; lower it or lengthen the cables')
            return
        end if
        zs_a = sqrt(zs_a)
        s = 0.0_dp
        do k = 1, ng
            phi = 0.25_dp*pi*(x(k) + 1.0_dp)
            q = amp*sin(phi)
            zs_q = sqrt(p%big_l**2 - h2(q))
            ! z(A) - z(q) = (h2(A) - h2(q)) / (zs(q) + zs(A)), h2(A) - h2(q) = B/2 (cos q - cos A)
            dv = p%big_b*sin(0.5_dp*(amp + q))*sin(0.5_dp*(amp - q))/(zs_q + zs_a)
            dz = 0.25_dp*p%big_b*sin(q)/zs_q
            jq = p%inertia(ivert) + dz**2
            s = s + w(k)*sqrt(jq/(2.0_dp*dv))*amp*cos(phi)
        end do
        period = 4.0_dp*0.25_dp*pi*s
    contains
        pure real(dp) function h2(qq)
            real(dp), intent(in) :: qq
            h2 = 0.25_dp + 0.25_dp*p%big_b**2 - 0.5_dp*p%big_b*cos(qq)
        end function h2
    end subroutine torsion_period

    !> Gauss-Legendre nodes and weights on [-1, 1] (Newton on P_n from the Chebyshev guess).
    pure subroutine gauss_legendre(x, w)
        real(dp), intent(out) :: x(:), w(:)
        integer :: n, i, j, it
        real(dp) :: z, p0, p1, p2, dp_dz, dz
        n = size(x)
        do i = 1, n
            z = cos(pi*(i - 0.25_dp)/(n + 0.5_dp))
            do it = 1, 100
                p0 = 1.0_dp
                p1 = z
                do j = 2, n
                    p2 = ((2*j - 1)*z*p1 - (j - 1)*p0)/j
                    p0 = p1
                    p1 = p2
                end do
                dp_dz = n*(z*p1 - p0)/(z*z - 1.0_dp)
                dz = p1/dp_dz
                z = z - dz
                if (abs(dz) < 1.0e-16_dp) exit
            end do
            x(i) = z
            w(i) = 2.0_dp/((1.0_dp - z*z)*dp_dz**2)
        end do
    end subroutine gauss_legendre

    !> Z = d f / d y of the chart right-hand side (eq. (51)), by central differences
    !! extrapolated (Richardson, h and h/2: error O(h^4)).
    subroutine jacobian_z(p, y, z, stat)
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        real(dp), intent(in) :: y(NSTATE)       !! chart state
        real(dp), intent(out) :: z(NSTATE, NSTATE)
        type(status_t), intent(out) :: stat
        real(dp) :: h, yp(NSTATE), d1(5), d2(5), ap(5), am(5)
        integer :: j
        z = 0.0_dp
        do j = 1, 5
            z(j, j + 5) = 1.0_dp
        end do
        do j = 1, NSTATE
            h = 2.0e-3_dp*max(1.0_dp, abs(y(j)))
            yp = y
            yp(j) = y(j) + h
            call chart_accelerations(p, yp, ap, stat)
            if (stat%code /= 0) return
            yp(j) = y(j) - h
            call chart_accelerations(p, yp, am, stat)
            if (stat%code /= 0) return
            d1 = (ap - am)/(2*h)
            yp(j) = y(j) + 0.5_dp*h
            call chart_accelerations(p, yp, ap, stat)
            if (stat%code /= 0) return
            yp(j) = y(j) - 0.5_dp*h
            call chart_accelerations(p, yp, am, stat)
            if (stat%code /= 0) return
            d2 = (ap - am)/h
            z(6:10, j) = (4*d2 - d1)/3
        end do
    end subroutine jacobian_z

    !> Orbit and dH/dt = Z H together: y(1:10) the state, y(11:110) H by columns.
    subroutine variational_rhs(sys, t, y, ydot, stat)
        class(variational_t), intent(inout) :: sys
        real(dp), intent(in) :: t, y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        real(dp) :: z(NSTATE, NSTATE), a(5)
        if (.false.) ydot(1) = t
        call chart_accelerations(sys%p, y(1:NSTATE), a, stat)
        if (stat%code /= 0) return
        ydot(1:5) = y(6:10)
        ydot(6:10) = a
        call jacobian_z(sys%p, y(1:NSTATE), z, stat)
        ydot(NSTATE + 1:NV) = reshape(matmul(z, reshape(y(NSTATE + 1:NV), [NSTATE, NSTATE])), &
                                      [NSTATE*NSTATE])
    end subroutine variational_rhs

    !> Monodromy H(t*) over one period from the chart state y0, as the product of `nseg`
    !! segment matrices (each integrated from H = I).
    subroutine monodromy(p, y0, period, nseg, rtol, h, yend, nsteps, nrhs, stat)
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        real(dp), intent(in) :: y0(NSTATE)      !! start of the orbit (chart state)
        real(dp), intent(in) :: period          !! t*
        integer, intent(in) :: nseg             !! shooting segments (>= 1)
        real(dp), intent(in) :: rtol            !! integrator tolerance
        real(dp), intent(out) :: h(NSTATE, NSTATE)  !! monodromy matrix
        real(dp), intent(out) :: yend(NSTATE)   !! state after one period
        integer, intent(out) :: nsteps, nrhs    !! integrator work
        type(status_t), intent(out) :: stat
        type(variational_t) :: sys
        type(lsoda_t) :: s
        type(lsoda_stats_t) :: st
        real(dp) :: y(NV), eye(NSTATE, NSTATE), t0, t1
        integer :: k, j
        sys%p = p
        eye = 0.0_dp
        do j = 1, NSTATE
            eye(j, j) = 1.0_dp
        end do
        h = eye
        y(1:NSTATE) = y0
        nsteps = 0
        nrhs = 0
        do k = 1, nseg
            t0 = period*(k - 1)/nseg
            t1 = period*k/nseg
            y(NSTATE + 1:NV) = reshape(eye, [NSTATE*NSTATE])
            call s%init(sys, t0, y, rtol, [rtol*1.0e-2_dp], stat, tcrit=t1)
            if (stat%code /= 0) return
            call s%integrate(sys, t1, y, stat)
            st = s%stats()
            nsteps = nsteps + st%steps
            nrhs = nrhs + st%rhs_evals
            if (stat%code /= 0) return
            h = matmul(reshape(y(NSTATE + 1:NV), [NSTATE, NSTATE]), h)
        end do
        yend = y(1:NSTATE)
    end subroutine monodromy

    !> The whole analysis at torsion amplitude `amp` (rad).
    subroutine floquet_analysis(p, amp, rtol, nseg, res, stat)
        type(pendulum_t), intent(in) :: p       !! scaled parameters (a torsion scene)
        real(dp), intent(in) :: amp             !! amplitude of theta4 (rad)
        real(dp), intent(in) :: rtol            !! integrator tolerance
        integer, intent(in) :: nseg             !! shooting segments
        type(floquet_result_t), intent(out) :: res
        type(status_t), intent(out) :: stat     !! ERR_DECK (scene), ERR_NUMERIC
        real(dp) :: th(5), y0(NSTATE), yend(NSTATE), h(NSTATE, NSTATE), dist(NSTATE)
        complex(dp) :: lam(NSTATE)
        integer :: ivert, k, idx(NSTATE), i
        call check_torsion_scene(p, ivert, stat)
        if (stat%code /= 0) return
        call torsion_period(p, amp, ivert, res%period, stat)
        if (stat%code /= 0) return
        call raised_angles(p, amp, th, stat)
        if (stat%code /= 0) return
        call solve_theta5(p, th, stat)
        if (stat%code /= 0) return
        y0 = chart_state(th, [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp])
        call monodromy(p, y0, res%period, nseg, rtol, h, yend, res%steps, &
                       res%rhs_evaluations, stat)
        if (stat%code /= 0) return
        res%orbit_closure = maxval(abs(yend - y0))
        call la_eig(h, lam, stat)
        if (stat%code /= 0) return
        ! sort by decreasing modulus
        idx = [(k, k=1, NSTATE)]
        do k = 2, NSTATE
            i = k
            do while (i > 1)
                if (abs(lam(idx(i))) <= abs(lam(idx(i - 1)))) exit
                idx([i - 1, i]) = idx([i, i - 1])
                i = i - 1
            end do
        end do
        res%multipliers = lam(idx)
        ! the four trivial multipliers (time shift and energy; the constraint and its rate)
        dist = abs(res%multipliers - (1.0_dp, 0.0_dp))
        res%trivial = .false.
        do k = 1, 4
            i = minloc(dist, 1, mask=.not. res%trivial)
            res%trivial(i) = .true.
        end do
        res%max_modulus = maxval(abs(res%multipliers), mask=.not. res%trivial)
        res%stable = res%max_modulus <= 1.0_dp + STABILITY_MARGIN
        if (.false.) call set_error(stat, ERR_NUMERIC, '')
    end subroutine floquet_analysis

end module floquet
