!> The multifilar platform with elastic cables (any n >= 2), in generalized coordinates
!! whose stiff part is linear: the free coordinates of the chart of platform_geometry and
!! the stretches of its master cables.  doc/theory.md, "Elastic cables, n cables".
!!
!! The coordinates.  Q = (q_F, s_1 ... s_m): the free coordinates (x, y, psi for n >= 3)
!! and the stretches s_j = l_j - L0_j of the m = min(n, 3) master cables; the pose is
!! solved from the cables as in the inextensible model with the masters' lengths
!! L0_j + s_j (solve_pose), so the masters' spring energies (k_j/2) s_j^2 are exactly
!! quadratic in Q and an implicit method's frozen Jacobian is right for them (the reason
!! of module elastic_gen, which this generalises from two cables to n).  For n <= 3 every
!! cable is a master; for n >= 4 the other cables' lengths follow the pose.  The state is
!! y = (Q, Q') (12).
!!
!! Each cable is a massless spring-dashpot along its straight line, pulling only when
!! stretched (elastic_model's law): with the stiffness k = EA/(m g) (nondimensional, every
!! cable) and the damping ratio zeta (relative to critical for the whole mass on one
!! cable's spring),
!!   k_i = k m g / L0_i,  c_i = 2 zeta m (k g / L0_i)^(1/2),
!!   T_i = k_i (l_i - L0_i) + c_i l_i'   when taut, 0 when slack.
!! A cable's mode (mode(i)): CABLE_AUTO (the law decided at each evaluation: taut when
!! l_i > L0_i and T_i > 0), CABLE_TAUT (the smooth law), CABLE_SLACK (T = 0); the run
!! driver (runs/platform_run) keeps the modes fixed within each step and switches them
!! where the switching function g_i = min(k_i (l_i - L0_i), T_i) changes sign.
!!
!! Kane's equations as in platform_model with six generalized speeds; a cable's
!! generalized force is -T_i dl_i/dQ_r: -T_j on its own stretch for a master j (exact, no
!! recomputation of its length), -T_i u_i . (vv_r + vw_r x R p_i) for the others.
module platform_elastic
    use kinds, only: dp
    use status, only: status_t, set_error, ERR_DECK, ERR_NUMERIC
    use text, only: sci, itoa
    use vectors, only: cross
    use ode_system, only: ode_system_t
    use lapack_wrap, only: la_small_chol, la_small_chol_solve, la_syev
    use platform_geometry, only: platform_t, platform_kin_t, platform_prepare, solve_pose, &
                                 platform_kinematics, rotation, PLATFORM_NMAX, QPSI, &
                                 set_reference, pose_guess_t, guess_pose, keep_guess
    use platform_model, only: kane_terms, platform_motion_t, platform_evaluate, rest_pose
    use unused_arg, only: unused
    implicit none
    private

    integer, parameter, public :: PE_NSTATE = 12    !! y = (Q(6), Q'(6))
    !> Cable modes: the law decided at each evaluation, taut, slack.
    integer, parameter, public :: CABLE_AUTO = 0, CABLE_TAUT = 1, CABLE_SLACK = 2

    !> The platform with elastic cables as an ODE system.
    type, extends(ode_system_t), public :: platform_elastic_t
        type(platform_t) :: pl                  !! the rig, prepared (its chart)
        real(dp) :: stiffness = 1.0e6_dp        !! k = EA/(m g) of every cable
        real(dp) :: damping = 0.0_dp            !! zeta of every cable
        real(dp) :: l0(PLATFORM_NMAX) = -1.0_dp !! natural lengths; <= 0: pl%length
        integer :: mode(PLATFORM_NMAX) = CABLE_AUTO
        type(pose_guess_t), private :: guess    !! the last pose (Newton's first guess)
    contains
        procedure :: rhs => pe_rhs
    end type platform_elastic_t

    !> The cables and the motion at one instant.
    type, public :: pe_motion_t
        real(dp) :: q(6) = 0.0_dp, qd(6) = 0.0_dp  !! pose and its rates
        real(dp) :: rc(3) = 0.0_dp, vc(3) = 0.0_dp, omega(3) = 0.0_dp
        real(dp) :: tension(PLATFORM_NMAX) = 0.0_dp    !! force units; 0 when slack
        real(dp) :: length(PLATFORM_NMAX) = 0.0_dp     !! |P_i - S_i|
        real(dp) :: length_rate(PLATFORM_NMAX) = 0.0_dp
        logical :: slack(PLATFORM_NMAX) = .false.      !! the law's state (not the mode)
        real(dp) :: spring_energy = 0.0_dp
        real(dp) :: energy = 0.0_dp             !! kinetic + m g z_c + spring energy
    end type pe_motion_t

    public :: pe_natural_lengths, pe_from_inextensible, pe_evaluate, pe_energy
    public :: pe_switch, pe_rest_pose, pe_start, pe_linearise, pe_cable_constants
    public :: pe_pose, pe_atol

contains

    !> The absolute tolerances of the state for the tolerance atol of a coordinate (m, rad):
    !! the coordinates and stretches atol, the free coordinates' rates atol (g/l)^(1/2), the
    !! stretches' rates atol (k g/l)^(1/2) (l the rig's size lscale).  With atol on every
    !! rate the stage iteration of an implicit method cannot meet its test: a cable that is
    !! not a master has its stretch from its length, l - L0, whose roundoff (eps l) pulls
    !! with k m g eps, and that noise in the accelerations moves the rates by more than
    !! atol over a step (Radau's Newton failing step after step).
    pure function pe_atol(el, atol) result(a)
        type(platform_elastic_t), intent(in) :: el
        real(dp), intent(in) :: atol
        real(dp) :: a(PE_NSTATE)
        integer :: nf
        nf = el%pl%nf
        a = atol
        a(7:6 + nf) = atol*sqrt(el%pl%gravity/el%pl%lscale)
        a(7 + nf:12) = atol*sqrt(max(1.0_dp, el%stiffness)*el%pl%gravity/el%pl%lscale)
    end function pe_atol

    !> Natural lengths L0_i (pl%length where l0 is not set).
    pure function pe_natural_lengths(el) result(l0)
        type(platform_elastic_t), intent(in) :: el
        real(dp) :: l0(el%pl%n)
        integer :: i
        do i = 1, el%pl%n
            l0(i) = el%pl%length(i)
            if (el%l0(i) > 0.0_dp) l0(i) = el%l0(i)
        end do
    end function pe_natural_lengths

    !> Spring constant k_i and dashpot c_i of cable i.
    pure subroutine pe_cable_constants(el, l0, kc, cc)
        type(platform_elastic_t), intent(in) :: el
        real(dp), intent(in) :: l0              !! its natural length
        real(dp), intent(out) :: kc, cc
        kc = el%stiffness*el%pl%mass*el%pl%gravity/l0
        cc = 2.0_dp*el%damping*el%pl%mass*sqrt(el%stiffness*el%pl%gravity/l0)
    end subroutine pe_cable_constants

    !> The tension of a cable in a mode: stretch e = l - L0 (a master's from its state, not
    !! recomputed from the length: at k = 1e7, l - L0 would lose 9 digits), its rate ld,
    !! natural length l0.
    pure real(dp) function tension_law(el, mode, e, ld, l0) result(tn)
        type(platform_elastic_t), intent(in) :: el
        integer, intent(in) :: mode
        real(dp), intent(in) :: e, ld, l0
        real(dp) :: kc, cc
        call pe_cable_constants(el, l0, kc, cc)
        tn = kc*e + cc*ld
        select case (mode)
        case (CABLE_SLACK)
            tn = 0.0_dp
        case (CABLE_AUTO)
            if (.not. (e > 0.0_dp .and. tn > 0.0_dp)) tn = 0.0_dp
        end select
    end function tension_law

    !> The switching function of a cable: g = min(k_i e, k_i e + c_i l'), e = l - L0;
    !! taut where g > 0.
    pure real(dp) function switch_of(el, e, ld, l0) result(g)
        type(platform_elastic_t), intent(in) :: el
        real(dp), intent(in) :: e, ld, l0
        real(dp) :: kc, cc
        call pe_cable_constants(el, l0, kc, cc)
        g = min(kc*e, kc*e + cc*ld)
    end function switch_of

    !> The pose and kinematics of state y (Q, Q'): q_D solved from the reference pose, or
    !! from the first-order guess of a nearby solved pose (g, updated).
    pure subroutine pe_pose(el, y, k, stat, g)
        type(platform_elastic_t), intent(in) :: el
        real(dp), intent(in) :: y(:)
        type(platform_kin_t), intent(out) :: k
        type(status_t), intent(out) :: stat
        type(pose_guess_t), intent(inout), optional :: g
        real(dp) :: q(6), lm(3), tr(6), l0
        integer :: nf, nd, j, i
        logical :: guessed
        nf = el%pl%nf
        nd = el%pl%nd
        guessed = .false.
        if (present(g)) then
            call guess_pose(el%pl, g, y(1:6), q, guessed)
        else
            q = el%pl%q_ref
            do j = 1, nf
                q(el%pl%free(j)) = y(j)
            end do
        end if
        lm = 0.0_dp
        do j = 1, nd
            i = el%pl%master(j)
            l0 = el%pl%length(i)
            if (el%l0(i) > 0.0_dp) l0 = el%l0(i)
            lm(j) = l0 + y(nf + j)
        end do
        call solve_pose(el%pl, q, lm, stat, from_ref=.not. guessed, tr=tr)
        if (stat%code /= 0) return
        call platform_kinematics(el%pl, q, y(7:6 + nf), lm, k, stat, sd=y(7 + nf:12), tr=tr)
        if (present(g) .and. stat%code == 0) call keep_guess(g, k, y(1:6))
    end subroutine pe_pose

    !> Every cable's length, stretch, length rate and tension in the cables' modes (modes:
    !! el%mode, or `modes` when given).  A master's stretch is its state s_j.
    pure subroutine cable_state(el, y, k, l, e, ld, tn, modes)
        type(platform_elastic_t), intent(in) :: el
        real(dp), intent(in) :: y(:)
        type(platform_kin_t), intent(in) :: k
        real(dp), intent(out) :: l(:), e(:), ld(:), tn(:)
        integer, intent(in), optional :: modes(:)
        real(dp) :: l0(el%pl%n)
        integer :: i, j, nf, md
        nf = el%pl%nf
        l0 = pe_natural_lengths(el)
        do i = 1, el%pl%n
            j = findloc(el%pl%master(1:el%pl%nd), i, 1)
            if (j > 0) then
                e(i) = y(nf + j)
                l(i) = l0(i) + e(i)
                ld(i) = y(6 + nf + j)
            else
                l(i) = norm2(k%d(:, i))
                e(i) = l(i) - l0(i)
                ld(i) = dot_product(k%d(:, i), k%pd(:, i))/l(i)
            end if
            md = el%mode(i)
            if (present(modes)) md = modes(i)
            tn(i) = tension_law(el, md, e(i), ld(i), l0(i))
        end do
    end subroutine cable_state

    !> Right-hand side: y' = (Q', M^-1 f).
    subroutine pe_rhs(sys, t, y, ydot, stat)
        class(platform_elastic_t), intent(inout) :: sys
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        call unused(t)
        call accelerations(sys, y, ydot, stat, g=sys%guess)
    end subroutine pe_rhs

    !> y' of state y in the cables' modes (g: the guess of the pose, updated).
    pure subroutine accelerations(el, y, ydot, stat, modes, g)
        type(platform_elastic_t), intent(in) :: el
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        integer, intent(in), optional :: modes(:)
        type(pose_guess_t), intent(inout), optional :: g
        type(platform_kin_t) :: k
        real(dp) :: mm(6, 6), f(6), u(3)
        real(dp), dimension(PLATFORM_NMAX) :: l, e, ld, tn
        integer :: i, j, c, nf, n
        nf = el%pl%nf
        n = el%pl%n
        ydot = 0.0_dp
        call pe_pose(el, y, k, stat, g)
        if (stat%code /= 0) return
        call kane_terms(el%pl, k, mm, f)
        call cable_state(el, y, k, l(1:n), e(1:n), ld(1:n), tn(1:n), modes)
        do i = 1, n
            if (tn(i) == 0.0_dp) cycle
            j = findloc(el%pl%master(1:el%pl%nd), i, 1)
            if (j > 0) then
                f(nf + j) = f(nf + j) - tn(i)
            else
                u = k%d(:, i)/norm2(k%d(:, i))
                do c = 1, 6
                    f(c) = f(c) - tn(i)*dot_product(u, k%vv(:, c) + &
                                                    cross(k%vw(:, c), k%rho(:, i)))
                end do
            end if
        end do
        call la_small_chol(6, mm, stat)
        if (stat%code /= 0) return
        call la_small_chol_solve(6, mm, f)
        ydot(1:6) = y(7:12)
        ydot(7:12) = f
    end subroutine accelerations

    !> The cables' switching functions g_i (taut where > 0) at state y: a master cable's from
    !! its stretch state and rate alone, the others' from the pose.
    pure subroutine pe_switch(el, y, g, stat)
        type(platform_elastic_t), intent(in) :: el
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: g(:)           !! (n)
        type(status_t), intent(out) :: stat
        type(platform_kin_t) :: k
        real(dp), dimension(PLATFORM_NMAX) :: l, e, ld, tn
        real(dp) :: l0(el%pl%n)
        integer :: i, j, n, nf
        n = el%pl%n
        nf = el%pl%nf
        g = 0.0_dp
        stat%code = 0
        l0 = pe_natural_lengths(el)
        if (n > el%pl%nd) then
            call pe_pose(el, y, k, stat)
            if (stat%code /= 0) return
            call cable_state(el, y, k, l(1:n), e(1:n), ld(1:n), tn(1:n))
        end if
        do j = 1, el%pl%nd
            i = el%pl%master(j)
            e(i) = y(nf + j)
            ld(i) = y(6 + nf + j)
        end do
        do i = 1, n
            g(i) = switch_of(el, e(i), ld(i), l0(i))
        end do
    end subroutine pe_switch

    !> The motion and the cables at state y (tensions by the law decided here, CABLE_AUTO).
    subroutine pe_evaluate(el, y, mo, stat)
        type(platform_elastic_t), intent(in) :: el
        real(dp), intent(in) :: y(:)
        type(pe_motion_t), intent(out) :: mo
        type(status_t), intent(out) :: stat
        type(platform_kin_t) :: k
        real(dp) :: jn(3, 3), l0(el%pl%n), e(PLATFORM_NMAX), kc, cc
        integer :: i, n, auto(PLATFORM_NMAX)
        n = el%pl%n
        call pe_pose(el, y, k, stat)
        if (stat%code /= 0) return
        auto = CABLE_AUTO
        call cable_state(el, y, k, mo%length(1:n), e(1:n), mo%length_rate(1:n), &
                         mo%tension(1:n), auto(1:n))
        l0 = pe_natural_lengths(el)
        mo%spring_energy = 0.0_dp
        do i = 1, n
            mo%slack(i) = .not. (mo%tension(i) > 0.0_dp)
            call pe_cable_constants(el, l0(i), kc, cc)
            if (e(i) > 0.0_dp) mo%spring_energy = mo%spring_energy + 0.5_dp*kc*e(i)**2
        end do
        mo%q = k%q
        mo%qd = k%qd
        mo%rc = k%q(1:3) + k%rhoc
        mo%omega = k%omega
        mo%vc = k%vr + cross(k%omega, k%rhoc)
        jn = matmul(k%rot, matmul(el%pl%inertia, transpose(k%rot)))
        mo%energy = 0.5_dp*el%pl%mass*dot_product(mo%vc, mo%vc) + &
                    0.5_dp*dot_product(k%omega, matmul(jn, k%omega)) + &
                    el%pl%mass*el%pl%gravity*mo%rc(3) + mo%spring_energy
    end subroutine pe_evaluate

    !> Total energy of state y (huge when the pose cannot be solved).
    function pe_energy(el, y) result(en)
        type(platform_elastic_t), intent(in) :: el
        real(dp), intent(in) :: y(:)
        real(dp) :: en
        type(pe_motion_t) :: mo
        type(status_t) :: st
        call pe_evaluate(el, y, mo, st)
        en = mo%energy
        if (st%code /= 0) en = huge(1.0_dp)
    end function pe_energy

    !> The elastic model of an inextensible platform's state (n <= 3, rest_pose done on
    !! el%pl): the natural lengths are set so that the cables have the inextensible
    !! model's tensions T_i at y_in, L0_i = l_i/(1 + T_i/(k m g)); the elastic state has
    !! the same pose and velocities, with stretches l_i - L0_i and stretch rates 0, so no
    !! stretching transient is excited.
    subroutine pe_from_inextensible(el, y_in, y, stat)
        type(platform_elastic_t), intent(inout) :: el
        real(dp), intent(in) :: y_in(:)         !! (2 nf) the inextensible state
        real(dp), intent(out) :: y(:)           !! (12)
        type(status_t), intent(out) :: stat
        type(platform_motion_t) :: mo
        integer :: j, i, nf
        nf = el%pl%nf
        y = 0.0_dp
        if (el%pl%n > 3) then
            call set_error(stat, ERR_DECK, 'pe_from_inextensible: n >= 4 has no '// &
                           'inextensible state')
            return
        end if
        call platform_evaluate(el%pl, y_in, mo, stat)
        if (stat%code /= 0) return
        do j = 1, el%pl%nd
            i = el%pl%master(j)
            el%l0(i) = el%pl%length(i)/(1.0_dp + mo%tension(j)/(el%stiffness*el%pl%mass* &
                                                                 el%pl%gravity))
            y(nf + j) = el%pl%length(i) - el%l0(i)
        end do
        y(1:nf) = y_in(1:nf)
        y(7:6 + nf) = y_in(nf + 1:2*nf)
    end subroutine pe_from_inextensible

    !> dV/dQ of V = m g z_c + sum of the springs' energies (all cables taut: the smooth
    !! law) at Q (rates 0).
    pure subroutine pe_gradient(el, qq, grad, stat)
        type(platform_elastic_t), intent(in) :: el
        real(dp), intent(in) :: qq(6)
        real(dp), intent(out) :: grad(6)
        type(status_t), intent(out) :: stat
        type(platform_kin_t) :: k
        real(dp) :: y(12), mm(6, 6), f(6), u(3)
        real(dp), dimension(PLATFORM_NMAX) :: l, e, ld, tn
        integer :: taut(PLATFORM_NMAX), i, j, c, nf, n
        n = el%pl%n
        nf = el%pl%nf
        y = 0.0_dp
        y(1:6) = qq
        grad = 0.0_dp
        call pe_pose(el, y, k, stat)
        if (stat%code /= 0) return
        call kane_terms(el%pl, k, mm, f)        ! at rest f = the weight's generalized force
        grad = -f
        taut = CABLE_TAUT
        call cable_state(el, y, k, l(1:n), e(1:n), ld(1:n), tn(1:n), taut(1:n))
        do i = 1, n
            j = findloc(el%pl%master(1:el%pl%nd), i, 1)
            if (j > 0) then
                grad(nf + j) = grad(nf + j) + tn(i)
            else
                u = k%d(:, i)/norm2(k%d(:, i))
                do c = 1, 6
                    grad(c) = grad(c) + tn(i)*dot_product(u, k%vv(:, c) + &
                                                          cross(k%vw(:, c), k%rho(:, i)))
                end do
            end if
        end do
    end subroutine pe_gradient

    !> The scale of coordinate c of Q (steps of the differences).
    pure real(dp) function q_scale(el, c)
        type(platform_elastic_t), intent(in) :: el
        integer, intent(in) :: c
        q_scale = 1.0_dp
        if (c > el%pl%nf) then
            q_scale = el%pl%lscale/max(1.0_dp, el%stiffness)
        else if (el%pl%free(c) <= 3) then
            q_scale = el%pl%lscale
        end if
    end function q_scale

    !> K = d2V/dQ2 at Q by central differences of the exact gradient (Richardson).
    subroutine pe_hessian(el, qq, kk, stat)
        type(platform_elastic_t), intent(in) :: el
        real(dp), intent(in) :: qq(6)
        real(dp), intent(out) :: kk(6, 6)
        type(status_t), intent(out) :: stat
        real(dp) :: gp(6), gm(6), k1(6, 6), k2(6, 6), qp(6), h
        integer :: c, pass
        do pass = 1, 2
            do c = 1, 6
                h = 2.0e-4_dp*q_scale(el, c)/pass
                qp = qq
                qp(c) = qq(c) + h
                call pe_gradient(el, qp, gp, stat)
                if (stat%code /= 0) return
                qp(c) = qq(c) - h
                call pe_gradient(el, qp, gm, stat)
                if (stat%code /= 0) return
                if (pass == 1) then
                    k1(:, c) = (gp - gm)/(2.0_dp*h)
                else
                    k2(:, c) = (gp - gm)/(2.0_dp*h)
                end if
            end do
        end do
        kk = (4.0_dp*k2 - k1)/3.0_dp
        kk = 0.5_dp*(kk + transpose(kk))
    end subroutine pe_hessian

    !> The elastic rest pose: dV/dQ = 0 by Newton's method (all cables taut), from the
    !! inextensible rest pose of the master cables with their natural lengths (n <= 3: the
    !! cables' lengths l_i with L0 as set); q_rest = Q there, and el%pl%q_ref the pose.
    !! ERR_DECK when none is found or a cable is slack there.
    subroutine pe_rest_pose(el, q_rest, stat)
        type(platform_elastic_t), intent(inout) :: el
        real(dp), intent(out) :: q_rest(6)
        type(status_t), intent(out) :: stat
        type(platform_kin_t) :: k
        type(pe_motion_t) :: mo
        real(dp) :: qq(6), g(6), gn(6), kk(6, 6), dq(6), sc(6), a, gnorm, gnew, y(12), &
                    l0(el%pl%n)
        type(status_t) :: st
        integer :: it, c, half, i
        logical :: done
        q_rest = 0.0_dp
        if (.not. el%pl%ready) then
            call platform_prepare(el%pl, stat)
            if (stat%code /= 0) return
        end if
        ! start: the masters' inextensible rest pose at their natural lengths
        l0 = pe_natural_lengths(el)
        block
            type(platform_t) :: pm
            pm = el%pl
            pm%length(1:pm%n) = l0
            call rest_pose(pm, st)
            if (st%code == 0) call set_reference(el%pl, pm%q_ref)
        end block
        qq = 0.0_dp
        qq(1:el%pl%nf) = el%pl%q_ref(el%pl%free(1:el%pl%nf))
        do c = 1, 6
            sc(c) = q_scale(el, c)
        end do
        done = .false.
        do it = 1, 80
            call pe_gradient(el, qq, g, stat)
            if (stat%code /= 0) exit
            call pe_hessian(el, qq, kk, stat)
            if (stat%code /= 0) exit
            dq = -g
            call solve6(kk, dq, st)
            if (st%code /= 0) then
                call set_error(stat, ERR_DECK, 'platform: no elastic rest pose (the '// &
                               'potential''s Hessian is singular)')
                exit
            end if
            gnorm = norm2(g*sc)
            a = 1.0_dp
            do half = 1, 40
                call pe_gradient(el, qq + a*dq, gn, st)
                gnew = huge(1.0_dp)
                if (st%code == 0) gnew = norm2(gn*sc)
                if (gnew < gnorm .or. all(abs(a*dq) <= 1.0e-8_dp*sc)) exit
                a = 0.5_dp*a
            end do
            qq = qq + a*dq
            if (done) exit
            ! converged: one more step polishes
            done = all(abs(a*dq(1:el%pl%nf)) <= 1.0e-12_dp*sc(1:el%pl%nf)) .and. &
                   all(abs(a*dq(el%pl%nf + 1:6)) <= 1.0e-14_dp*el%pl%lscale)
        end do
        if (stat%code /= 0) return
        if (.not. done) then
            call set_error(stat, ERR_DECK, 'platform: no elastic rest pose found (Newton '// &
                           'did not converge)')
            return
        end if
        y = 0.0_dp
        y(1:6) = qq
        call pe_pose(el, y, k, stat)
        if (stat%code /= 0) return
        call set_reference(el%pl, k%q)
        q_rest = qq
        call pe_evaluate(el, y, mo, stat)
        if (stat%code /= 0) return
        do i = 1, el%pl%n
            if (mo%slack(i)) then
                call set_error(stat, ERR_DECK, 'platform: cable '//itoa(i)//' is slack at '// &
                               'rest (length '//sci(mo%length(i))//' <= natural length '// &
                               sci(l0(i))//'); shorten it or move cg_offset')
                return
            end if
        end do
    end subroutine pe_rest_pose

    !> x = A^-1 x, A 6 x 6 (LU with partial pivoting).
    pure subroutine solve6(a, x, stat)
        real(dp), intent(in) :: a(6, 6)
        real(dp), intent(inout) :: x(6)
        type(status_t), intent(out) :: stat
        real(dp) :: lu(6, 6), t(6), f
        integer :: i, j, p
        stat%code = 0
        lu = a
        do j = 1, 6
            p = j - 1 + maxloc(abs(lu(j:6, j)), 1)
            if (.not. (abs(lu(p, j)) > 0.0_dp)) then
                call set_error(stat, ERR_NUMERIC, 'platform: singular matrix')
                return
            end if
            if (p /= j) then
                t = lu(j, :); lu(j, :) = lu(p, :); lu(p, :) = t
                f = x(j); x(j) = x(p); x(p) = f
            end if
            do i = j + 1, 6
                f = lu(i, j)/lu(j, j)
                lu(i, j:6) = lu(i, j:6) - f*lu(j, j:6)
                x(i) = x(i) - f*x(j)
            end do
        end do
        do i = 6, 1, -1
            x(i) = (x(i) - dot_product(lu(i, i + 1:6), x(i + 1:6)))/lu(i, i)
        end do
    end subroutine solve6

    !> The start of an elastic run from the rest pose q_rest (pe_rest_pose): the body turned
    !! by `amplitude` about the vertical through its mass centre (or `centre`) and moved by
    !! `sway`, the masters' stretches those at which their accelerations vanish (the cables
    !! carry what the body's motion asks of them), released at rest.
    subroutine pe_start(el, q_rest, amplitude, y0, stat, sway, centre)
        type(platform_elastic_t), intent(in) :: el
        real(dp), intent(in) :: q_rest(6)
        real(dp), intent(in) :: amplitude
        real(dp), intent(out) :: y0(12)
        type(status_t), intent(out) :: stat
        real(dp), intent(in), optional :: sway(2), centre(2)
        real(dp) :: q(6), r(3, 3), c(2), u(2), ca, sa, qf(6), ds(3), yd(12), yp(12), &
                    ydp(12), jac(3, 3), h
        type(platform_kin_t) :: k
        integer :: nf, nd, j, it
        nf = el%pl%nf
        y0 = 0.0_dp
        q = el%pl%q_ref
        r = rotation(q(4), q(5), q(6))
        c = q(1:2) + matmul(r(1:2, :), el%pl%cg)
        if (present(centre)) c = centre
        ca = cos(amplitude)
        sa = sin(amplitude)
        u = q(1:2) - c
        q(1:2) = c + [ca*u(1) - sa*u(2), sa*u(1) + ca*u(2)]
        q(QPSI) = q(QPSI) + amplitude
        if (present(sway)) q(1:2) = q(1:2) + sway
        qf = q_rest
        do j = 1, nf
            qf(j) = q(el%pl%free(j))
        end do
        ! the stretches where the stretches' accelerations vanish (Newton, the Jacobian by
        ! differences): the start lies on the slow motion, the cables carry what the body's
        ! motion asks of them, and no stretching oscillation is excited beyond O(1/k^2)
        nd = 6 - nf
        y0 = 0.0_dp
        y0(1:6) = qf
        do it = 1, 8
            call accelerations(el, y0, yd, stat)
            if (stat%code /= 0) exit
            h = 1.0e-3_dp*el%pl%lscale/max(1.0_dp, el%stiffness)
            do j = 1, nd
                yp = y0
                yp(nf + j) = y0(nf + j) + h
                call accelerations(el, yp, ydp, stat)
                if (stat%code /= 0) exit
                jac(1:nd, j) = (ydp(6 + nf + 1:12) - yd(6 + nf + 1:12))/h
            end do
            if (stat%code /= 0) exit
            ds(1:nd) = -yd(6 + nf + 1:12)
            call solve_lu(nd, jac(1:nd, 1:nd), ds(1:nd))
            y0(nf + 1:6) = y0(nf + 1:6) + ds(1:nd)
            if (all(abs(ds(1:nd)) <= 1.0e-15_dp*el%pl%lscale)) exit
        end do
        qf = y0(1:6)
        y0(1:6) = qf
        call pe_pose(el, y0, k, stat)
        if (stat%code /= 0) then
            stat%code = ERR_DECK
            stat%msg = 'platform start: the cables cannot hold the body there; lower the '// &
                       'amplitude or the sway'
        end if
    contains
        !> x = a^-1 x (order m <= 3, LU with partial pivoting).
        pure subroutine solve_lu(m, a, x)
            integer, intent(in) :: m
            real(dp), intent(in) :: a(m, m)
            real(dp), intent(inout) :: x(m)
            real(dp) :: lu(m, m), row(m), f
            integer :: i, jj, p
            lu = a
            do jj = 1, m
                p = jj - 1 + maxloc(abs(lu(jj:m, jj)), 1)
                if (lu(p, jj) == 0.0_dp) then
                    x = 0.0_dp
                    return
                end if
                if (p /= jj) then
                    row = lu(jj, :); lu(jj, :) = lu(p, :); lu(p, :) = row
                    f = x(jj); x(jj) = x(p); x(p) = f
                end if
                do i = jj + 1, m
                    f = lu(i, jj)/lu(jj, jj)
                    lu(i, jj:m) = lu(i, jj:m) - f*lu(jj, jj:m)
                    x(i) = x(i) - f*x(jj)
                end do
            end do
            do i = m, 1, -1
                x(i) = (x(i) - dot_product(lu(i, i + 1:m), x(i + 1:m)))/lu(i, i)
            end do
        end subroutine solve_lu
    end subroutine pe_start

    !> The small oscillations about the rest pose q_rest: K = d2V/dQ2 (taut cables), M the
    !! generalized inertia; omega2 the eigenvalues of M^-1 K, ascending.
    subroutine pe_linearise(el, q_rest, omega2, stat, kk_out, mm_out)
        type(platform_elastic_t), intent(in) :: el
        real(dp), intent(in) :: q_rest(6)
        real(dp), intent(out) :: omega2(6)
        type(status_t), intent(out) :: stat
        real(dp), intent(out), optional :: kk_out(6, 6), mm_out(6, 6)
        type(platform_kin_t) :: k
        real(dp) :: y(12), mm(6, 6), f(6), kk(6, 6), l(6, 6), linv(6, 6), a(6, 6), z(6, 6)
        integer :: c, i
        y = 0.0_dp
        y(1:6) = q_rest
        omega2 = 0.0_dp
        call pe_pose(el, y, k, stat)
        if (stat%code /= 0) return
        call kane_terms(el%pl, k, mm, f)
        call pe_hessian(el, q_rest, kk, stat)
        if (stat%code /= 0) return
        if (present(kk_out)) kk_out = kk
        if (present(mm_out)) mm_out = mm
        l = mm
        call la_small_chol(6, l, stat)
        if (stat%code /= 0) return
        linv = 0.0_dp
        do c = 1, 6
            linv(c, c) = 1.0_dp
            do i = 1, 6
                linv(i, c) = (linv(i, c) - dot_product(l(i, 1:i - 1), linv(1:i - 1, c)))/l(i, i)
            end do
        end do
        a = matmul(linv, matmul(kk, transpose(linv)))
        a = 0.5_dp*(a + transpose(a))
        call la_syev(a, omega2, z, stat)
    end subroutine pe_linearise

end module platform_elastic
