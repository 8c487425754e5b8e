!> The multifilar platform with inextensible cables (n = 2 or 3): Kane's equations in the
!! chart of module platform_geometry, the rest pose, the start, tensions, energy, the
!! linearised model and the tipping height.  doc/theory.md, "The multifilar platform".
!!
!! Kane's equations.  The generalized speeds are the free coordinates' rates u = q_F'
!! (x', y', psi' for n = 3; and the swing about the line of the two body points for n = 2).
!! With the mass centre's partial velocities vc_r = vv_r + vw_r x R c, the partial angular
!! velocities vw_r, and the accelerations at u' = 0 (a_c0, alpha_0) of platform_kinematics:
!!   F_r  = vc_r . (-m g n3) + vw_r . tau_d            (the cables do no work)
!!   F*_r = -vc_r . m a_c - vw_r . (J alpha + omega x J omega)     (J = R J_B R^T)
!! and F_r + F*_r = 0 reads M u' = f with
!!   M_rs = m vc_r . vc_s + vw_r . J vw_s,
!!   f_r  = -vc_r . m (a_c0 + g n3) + vw_r . (tau_d - J alpha_0 - omega x J omega),
!! a symmetric positive definite system of order nf, solved by Cholesky.  tau_d is the
!! damping torque about the vertical (platform_t c_v, c_q).  The state of the ODE is
!! y = (q_F, q_F') (platform_nstate: 6 for n = 3, 8 for n = 2); q_D is solved from the
!! constraints at every evaluation (solve_pose), so the constraints hold to roundoff and
!! no drift needs correcting.  The right-hand side starts Newton from the pose of its last
!! evaluation moved to first order (pose_guess_t): two iterations where the reference pose
!! would take three or four.  The Jacobian is the integrators' differences.
!!
!! The API: check_platform (the inputs, the chart, the rest pose, its stability, one line
!! when refused), rest_pose, platform_start (turned by an amplitude about the vertical,
!! moved, swung), platform_sys_t (the ODE system), platform_evaluate (pose, rates,
!! accelerations, tensions, energy, residual, the chart's quality), platform_energy,
!! linearise (K, M, omega^2, the mode shapes), tipping_depth.
!!
!! The tensions are the constraints' multipliers: with w the force and the moment about the
!! body's origin that the cables must supply (Newton-Euler: m (a_c + g n3), and
!! R c x m (a_c + g n3) + J alpha + omega x J omega - tau_d), A_D^T lambda = E_D^T w, and
!! T_i = -lambda_i l_i.  A tension <= 0 ends the model's validity (runs/platform_run).
module platform_model
    use kinds, only: dp, pi
    use status, only: status_t, set_error, ERR_DECK, ERR_MODEL, ERR_NUMERIC
    use text, only: sci, itoa, fixed
    use vectors, only: cross
    use ode_system, only: ode_system_t
    use lapack_wrap, only: la_small_chol, la_small_chol_solve, la_syev
    use platform_geometry, only: platform_t, platform_kin_t, platform_prepare, solve_pose, &
                                 platform_kinematics, rotation, QZ, QTHETA, QPHI, QPSI, &
                                 set_reference, pose_guess_t, guess_pose, keep_guess, &
                                 chart_quality
    use unused_arg, only: unused
    implicit none
    private

    !> The platform with inextensible cables as an ODE system, y = (q_F, q_F').
    type, extends(ode_system_t), public :: platform_sys_t
        type(platform_t) :: pl
        !> .true.: each right-hand side keeps its state and the cable tensions there
        !! (last_tensions), for the validity check at the end of each step
        logical :: keep_tensions = .false.
        logical, private :: have_last = .false.
        type(pose_guess_t), private :: guess     !! the last pose (Newton's first guess)
        real(dp), private :: last_y(8) = 0.0_dp
        real(dp), private :: last_t(3) = 0.0_dp
        real(dp), private :: last_q(6) = 0.0_dp
    contains
        procedure :: rhs => platform_rhs
        procedure :: last_tensions
    end type platform_sys_t

    !> Everything about the motion at one instant.
    type, public :: platform_motion_t
        real(dp) :: q(6) = 0.0_dp, qd(6) = 0.0_dp  !! pose (x, y, z, psi, theta, phi), rates
        real(dp) :: udot(4) = 0.0_dp            !! the free coordinates' accelerations
        real(dp) :: rc(3) = 0.0_dp, vc(3) = 0.0_dp, ac(3) = 0.0_dp  !! mass centre
        real(dp) :: omega(3) = 0.0_dp, alpha(3) = 0.0_dp
        real(dp) :: tension(3) = 0.0_dp         !! cable tensions (force units)
        real(dp) :: energy = 0.0_dp             !! kinetic + potential (0 at z_c = 0)
        real(dp) :: residual = 0.0_dp           !! max_i ||P_i - S_i| - l_i|
        real(dp) :: quality = 0.0_dp            !! the chart's regularity
    end type platform_motion_t

    !> The small oscillations about the rest pose (linearise).
    type, public :: platform_modes_t
        integer :: nf = 0                       !! degrees of freedom
        real(dp) :: stiffness(4, 4) = 0.0_dp    !! K = d2V/dq_F2
        real(dp) :: mass(4, 4) = 0.0_dp         !! M of Kane's equations at rest
        real(dp) :: omega2(4) = 0.0_dp          !! eigenvalues of M^-1 K, ascending
        real(dp) :: shapes(4, 4) = 0.0_dp       !! their eigenvectors in q_F (columns)
    end type platform_modes_t

    public :: platform_nstate, platform_evaluate, platform_energy, rest_pose, linearise
    public :: platform_start, tipping_depth, check_platform, kane_terms, pose_of_state
    public :: potential_gradient

contains

    !> Size of the state: 2 nf.
    pure integer function platform_nstate(pl)
        type(platform_t), intent(in) :: pl
        platform_nstate = 2*pl%nf
    end function platform_nstate

    !> The pose and kinematics of state y: q_D solved from the reference pose, or from the
    !! first-order guess of a nearby solved pose (g, updated).
    pure subroutine pose_of_state(pl, y, k, stat, g)
        type(platform_t), intent(in) :: pl
        real(dp), intent(in) :: y(:)
        type(platform_kin_t), intent(out) :: k
        type(status_t), intent(out) :: stat
        type(pose_guess_t), intent(inout), optional :: g
        real(dp) :: q(6), lm(3), tr(6)
        integer :: nf, j
        logical :: guessed
        nf = pl%nf
        lm = 0.0_dp
        do j = 1, pl%nd
            lm(j) = pl%length(pl%master(j))
        end do
        guessed = .false.
        if (present(g)) then
            call guess_pose(pl, g, y(1:nf), q, guessed)
        else
            q = pl%q_ref
            do j = 1, nf
                q(pl%free(j)) = y(j)
            end do
        end if
        call solve_pose(pl, q, lm, stat, from_ref=.not. guessed, tr=tr)
        if (stat%code /= 0) return
        call platform_kinematics(pl, q, y(nf + 1:2*nf), lm, k, stat, tr=tr)
        if (present(g) .and. stat%code == 0) call keep_guess(g, k, y(1:nf))
    end subroutine pose_of_state

    !> The generalized inertia matrix mm (ns x ns, full) and the generalized forces f of
    !! gravity, the inertia's velocity terms and the damping about the vertical.
    pure subroutine kane_terms(pl, k, mm, f)
        type(platform_t), intent(in) :: pl
        type(platform_kin_t), intent(in) :: k
        real(dp), intent(out) :: mm(:, :)       !! (ns, ns)
        real(dp), intent(out) :: f(:)           !! (ns)
        real(dp) :: jn(3, 3), vc(3, 6), jw(3, 6), ac0(3), h(3), tq(3), g3(3)
        integer :: c, e, ns
        ns = k%ns
        jn = matmul(k%rot, matmul(pl%inertia, transpose(k%rot)))
        do c = 1, ns
            vc(:, c) = k%vv(:, c) + cross(k%vw(:, c), k%rhoc)
            jw(:, c) = matmul(jn, k%vw(:, c))
        end do
        ac0 = k%a0 + cross(k%al0, k%rhoc) + cross(k%omega, cross(k%omega, k%rhoc))
        h = matmul(jn, k%al0) + cross(k%omega, matmul(jn, k%omega))
        tq = damping_torque(pl, k%omega)
        g3 = pl%mass*(ac0 + [0.0_dp, 0.0_dp, pl%gravity])
        do c = 1, ns
            do e = 1, c
                mm(c, e) = pl%mass*dot_product(vc(:, c), vc(:, e)) + &
                           dot_product(k%vw(:, c), jw(:, e))
                mm(e, c) = mm(c, e)
            end do
            f(c) = -dot_product(vc(:, c), g3) + dot_product(k%vw(:, c), tq - h)
        end do
    end subroutine kane_terms

    !> The damping torque about the vertical: -(c_v W + c_q |W| W) n3, W = omega . n3.
    pure function damping_torque(pl, omega) result(tq)
        type(platform_t), intent(in) :: pl
        real(dp), intent(in) :: omega(3)
        real(dp) :: tq(3)
        tq = [0.0_dp, 0.0_dp, -(pl%c_v + pl%c_q*abs(omega(3)))*omega(3)]
    end function damping_torque

    !> Right-hand side: y' = (q_F', M^-1 f).
    subroutine platform_rhs(sys, t, y, ydot, stat)
        class(platform_sys_t), intent(inout) :: sys
        real(dp), intent(in) :: t               !! time (not used: autonomous)
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        type(platform_kin_t) :: k
        real(dp) :: mm(4, 4), f(4)
        integer :: nf
        call unused(t)
        nf = sys%pl%nf
        ydot = 0.0_dp
        call pose_of_state(sys%pl, y, k, stat, sys%guess)
        if (stat%code /= 0) return
        call kane_terms(sys%pl, k, mm(1:nf, 1:nf), f(1:nf))
        call spd_solve(nf, mm, f, stat)
        if (stat%code /= 0) return
        ydot(1:nf) = y(nf + 1:2*nf)
        ydot(nf + 1:2*nf) = f(1:nf)
        if (sys%keep_tensions) then
            sys%last_y(1:2*nf) = y(1:2*nf)
            sys%last_q = k%q
            sys%last_t(1:sys%pl%nd) = tensions_of(sys%pl, k, f(1:nf))
            sys%have_last = .true.
        end if
    end subroutine platform_rhs

    !> f = M^-1 f for the generalized inertia M (order n = 3 or 4, symmetric positive
    !! definite): Cholesky written out for n = 3, la_small_chol otherwise.
    pure subroutine spd_solve(n, mm, f, stat)
        integer, intent(in) :: n
        real(dp), intent(inout) :: mm(4, 4)
        real(dp), intent(inout) :: f(4)
        type(status_t), intent(out) :: stat
        real(dp) :: l11, l21, l31, l22, l32, l33, y1, y2, y3
        stat%code = 0
        if (n /= 3) then
            call la_small_chol(n, mm(1:n, 1:n), stat)
            if (stat%code /= 0) return
            call la_small_chol_solve(n, mm(1:n, 1:n), f(1:n))
            return
        end if
        if (.not. (mm(1, 1) > 0.0_dp)) then
            call set_error(stat, ERR_NUMERIC, 'platform: generalized inertia not positive')
            return
        end if
        l11 = sqrt(mm(1, 1))
        l21 = mm(2, 1)/l11
        l31 = mm(3, 1)/l11
        l22 = mm(2, 2) - l21*l21
        if (.not. (l22 > 0.0_dp)) then
            call set_error(stat, ERR_NUMERIC, 'platform: generalized inertia not positive')
            return
        end if
        l22 = sqrt(l22)
        l32 = (mm(3, 2) - l31*l21)/l22
        l33 = mm(3, 3) - l31*l31 - l32*l32
        if (.not. (l33 > 0.0_dp)) then
            call set_error(stat, ERR_NUMERIC, 'platform: generalized inertia not positive')
            return
        end if
        l33 = sqrt(l33)
        y1 = f(1)/l11
        y2 = (f(2) - l21*y1)/l22
        y3 = (f(3) - l31*y1 - l32*y2)/l33
        f(3) = y3/l33
        f(2) = (y2 - l32*f(3))/l22
        f(1) = (y1 - l21*f(2) - l31*f(3))/l11
    end subroutine spd_solve

    !> The state of the last right-hand side, the cable tensions and the pose there
    !! (keep_tensions); found = .false. when none was kept.
    subroutine last_tensions(sys, y, tension, found, q)
        class(platform_sys_t), intent(in) :: sys
        real(dp), intent(out) :: y(:)
        real(dp), intent(out) :: tension(:)
        logical, intent(out) :: found
        real(dp), intent(out), optional :: q(6)
        found = sys%have_last
        y = sys%last_y(1:size(y))
        tension = sys%last_t(1:size(tension))
        if (present(q)) q = sys%last_q
    end subroutine last_tensions

    !> The tensions of the master cables (all of them, n <= 3) from the accelerations udot.
    pure function tensions_of(pl, k, udot) result(tn)
        type(platform_t), intent(in) :: pl
        type(platform_kin_t), intent(in) :: k
        real(dp), intent(in) :: udot(:)
        real(dp) :: tn(pl%nd)
        real(dp) :: ar(3), al(3), ac(3), fn(3), jn(3, 3), tau(3), rhs(3), lam(3)
        integer :: j
        ar = k%a0 + matmul(k%vv(:, 1:k%ns), udot)
        al = k%al0 + matmul(k%vw(:, 1:k%ns), udot)
        ac = ar + cross(al, k%rhoc) + cross(k%omega, cross(k%omega, k%rhoc))
        fn = pl%mass*(ac + [0.0_dp, 0.0_dp, pl%gravity])
        jn = matmul(k%rot, matmul(pl%inertia, transpose(k%rot)))
        tau = cross(k%rhoc, fn) + matmul(jn, al) + cross(k%omega, matmul(jn, k%omega)) - &
              damping_torque(pl, k%omega)
        do j = 1, pl%nd
            select case (pl%dep(j))
            case (QZ)
                rhs(j) = fn(3)
            case (QTHETA)
                rhs(j) = dot_product(k%a2, tau)
            case (QPHI)
                rhs(j) = dot_product(k%a1, tau)
            end select
        end do
        lam(1:pl%nd) = matmul(transpose(k%adinv(1:pl%nd, 1:pl%nd)), rhs(1:pl%nd))
        do j = 1, pl%nd
            tn(j) = -lam(j)*pl%length(pl%master(j))
        end do
    end function tensions_of

    !> The motion at state y: pose, rates, accelerations, tensions, energy, residual.
    subroutine platform_evaluate(pl, y, mo, stat)
        type(platform_t), intent(in) :: pl
        real(dp), intent(in) :: y(:)
        type(platform_motion_t), intent(out) :: mo
        type(status_t), intent(out) :: stat
        type(platform_kin_t) :: k
        real(dp) :: mm(4, 4), f(4), jn(3, 3)
        integer :: nf, i
        nf = pl%nf
        call pose_of_state(pl, y, k, stat)
        if (stat%code /= 0) return
        call kane_terms(pl, k, mm(1:nf, 1:nf), f(1:nf))
        call la_small_chol(nf, mm(1:nf, 1:nf), stat)
        if (stat%code /= 0) return
        call la_small_chol_solve(nf, mm(1:nf, 1:nf), f(1:nf))
        mo%q = k%q
        mo%qd = k%qd
        mo%udot(1:nf) = f(1:nf)
        mo%rc = k%q(1:3) + k%rhoc
        mo%omega = k%omega
        mo%vc = k%vr + cross(k%omega, k%rhoc)
        mo%alpha = k%al0 + matmul(k%vw(:, 1:nf), f(1:nf))
        mo%ac = k%a0 + matmul(k%vv(:, 1:nf), f(1:nf)) + cross(mo%alpha, k%rhoc) + &
                cross(k%omega, cross(k%omega, k%rhoc))
        mo%tension(1:pl%nd) = tensions_of(pl, k, f(1:nf))
        jn = matmul(k%rot, matmul(pl%inertia, transpose(k%rot)))
        mo%energy = 0.5_dp*pl%mass*dot_product(mo%vc, mo%vc) + &
                    0.5_dp*dot_product(k%omega, matmul(jn, k%omega)) + &
                    pl%mass*pl%gravity*mo%rc(3)
        mo%residual = 0.0_dp
        do i = 1, pl%n
            mo%residual = max(mo%residual, abs(norm2(k%d(:, i)) - pl%length(i)))
        end do
        mo%quality = chart_quality(pl, k%q)
    end subroutine platform_evaluate

    !> Kinetic + potential energy of state y (m g z_c, 0 at z_c = 0).
    function platform_energy(pl, y) result(en)
        type(platform_t), intent(in) :: pl
        real(dp), intent(in) :: y(:)
        real(dp) :: en
        type(platform_motion_t) :: mo
        type(status_t) :: st
        call platform_evaluate(pl, y, mo, st)
        en = mo%energy
        if (st%code /= 0) en = huge(1.0_dp)
    end function platform_energy

    !> dV/dq_F of V = m g z_c at the free coordinates qf (rates 0): m g vc_r . n3.
    pure subroutine potential_gradient(pl, qf, grad, v, stat)
        type(platform_t), intent(in) :: pl
        real(dp), intent(in) :: qf(:)           !! (nf)
        real(dp), intent(out) :: grad(:)        !! (nf)
        real(dp), intent(out) :: v              !! V
        type(status_t), intent(out) :: stat
        type(platform_kin_t) :: k
        real(dp) :: y(8)
        integer :: c, nf
        nf = pl%nf
        y = 0.0_dp
        y(1:nf) = qf(1:nf)
        grad = 0.0_dp
        v = 0.0_dp
        call pose_of_state(pl, y(1:2*nf), k, stat)
        if (stat%code /= 0) return
        do c = 1, nf
            grad(c) = pl%mass*pl%gravity*(k%vv(3, c) + vw_cross_z(k%vw(:, c), k%rhoc))
        end do
        v = pl%mass*pl%gravity*(k%q(3) + k%rhoc(3))
    end subroutine potential_gradient

    !> (a x b) . n3
    pure real(dp) function vw_cross_z(a, b)
        real(dp), intent(in) :: a(3), b(3)
        vw_cross_z = a(1)*b(2) - a(2)*b(1)
    end function vw_cross_z

    !> The scale of free coordinate c: the length scale for x, y, z, 1 for the angles.
    pure real(dp) function coord_scale(pl, c)
        type(platform_t), intent(in) :: pl
        integer, intent(in) :: c
        coord_scale = 1.0_dp
        if (pl%free(c) <= 3) coord_scale = pl%lscale
    end function coord_scale

    !> The Hessian K = d2V/dq_F2 at qf: central differences of the analytic gradient at
    !! steps h and h/2 combined by Richardson's extrapolation (error O(h^4)), symmetrised.
    subroutine potential_hessian(pl, qf, kk, stat)
        type(platform_t), intent(in) :: pl
        real(dp), intent(in) :: qf(:)
        real(dp), intent(out) :: kk(:, :)       !! (nf, nf)
        type(status_t), intent(out) :: stat
        real(dp) :: gp(4), gm(4), k1(4, 4), k2(4, 4), qq(4), h, v
        integer :: c, nf, pass
        nf = pl%nf
        kk = 0.0_dp
        do pass = 1, 2
            do c = 1, nf
                h = 2.0e-4_dp*coord_scale(pl, c)/pass
                qq(1:nf) = qf(1:nf)
                qq(c) = qf(c) + h
                call potential_gradient(pl, qq(1:nf), gp(1:nf), v, stat)
                if (stat%code /= 0) return
                qq(c) = qf(c) - h
                call potential_gradient(pl, qq(1:nf), gm(1:nf), v, stat)
                if (stat%code /= 0) return
                if (pass == 1) then
                    k1(1:nf, c) = (gp(1:nf) - gm(1:nf))/(2.0_dp*h)
                else
                    k2(1:nf, c) = (gp(1:nf) - gm(1:nf))/(2.0_dp*h)
                end if
            end do
        end do
        kk(1:nf, 1:nf) = (4.0_dp*k2(1:nf, 1:nf) - k1(1:nf, 1:nf))/3.0_dp
        kk(1:nf, 1:nf) = 0.5_dp*(kk(1:nf, 1:nf) + transpose(kk(1:nf, 1:nf)))
    end subroutine potential_hessian

    !> The rest pose: the equilibrium under gravity (dV/dq_F = 0) found by Newton's method
    !! from the reference pose (the Hessian by differences of the exact gradient, steps
    !! halved while the gradient's norm grows); it becomes the reference pose pl%q_ref.
    !! ERR_DECK when no equilibrium is found.  Stability is not judged here (linearise).
    subroutine rest_pose(pl, stat)
        type(platform_t), intent(inout) :: pl
        type(status_t), intent(out) :: stat
        real(dp) :: qf(4), g(4), gn(4), kk(4, 4), dq(4), v, a, sc(4), gnorm, gnew
        type(platform_kin_t) :: k
        type(status_t) :: st
        integer :: it, nf, c, half
        logical :: done
        nf = pl%nf
        qf(1:nf) = pl%q_ref(pl%free(1:nf))
        do c = 1, nf
            sc(c) = coord_scale(pl, c)
        end do
        done = .false.
        do it = 1, 60
            call potential_gradient(pl, qf(1:nf), g(1:nf), v, stat)
            if (stat%code /= 0) exit
            call potential_hessian(pl, qf(1:nf), kk(1:nf, 1:nf), stat)
            if (stat%code /= 0) exit
            dq(1:nf) = -g(1:nf)
            call solve_sym(nf, kk(1:nf, 1:nf), dq(1:nf), st)
            if (st%code /= 0) then
                call set_error(stat, ERR_DECK, 'platform: no rest pose (the potential''s '// &
                               'Hessian is singular)')
                exit
            end if
            gnorm = norm2(g(1:nf)*sc(1:nf))
            ! the gradient at roundoff: done (also where K is nearly singular, at the
            ! tipping height, and its steps would only follow the roundoff)
            if (gnorm <= 1.0e-14_dp*pl%mass*pl%gravity*pl%lscale) then
                done = .true.
                exit
            end if
            a = 1.0_dp
            do half = 1, 30
                call potential_gradient(pl, qf(1:nf) + a*dq(1:nf), gn(1:nf), v, st)
                gnew = huge(1.0_dp)
                if (st%code == 0) gnew = norm2(gn(1:nf)*sc(1:nf))
                if (gnew < gnorm .or. all(abs(a*dq(1:nf)) <= 1.0e-8_dp*sc(1:nf))) exit
                a = 0.5_dp*a
            end do
            qf(1:nf) = qf(1:nf) + a*dq(1:nf)
            if (all(abs(a*dq(1:nf)) <= 1.0e-13_dp*sc(1:nf))) then
                done = .true.
                exit
            end if
        end do
        if (stat%code /= 0) return
        if (.not. done) then
            call set_error(stat, ERR_DECK, 'platform: no rest pose found (Newton did not '// &
                           'converge in 60 iterations)')
            return
        end if
        g = 0.0_dp
        call pose_of_state(pl, [qf(1:nf), g(1:nf)], k, stat)
        if (stat%code /= 0) return
        call set_reference(pl, k%q)
    end subroutine rest_pose

    !> x = A^-1 x for a symmetric A of order n <= 4 (LU with partial pivoting: A need not
    !! be definite).
    pure subroutine solve_sym(n, a, x, stat)
        integer, intent(in) :: n
        real(dp), intent(in) :: a(n, n)
        real(dp), intent(inout) :: x(n)
        type(status_t), intent(out) :: stat
        real(dp) :: lu(n, n), t(n), piv, f
        integer :: i, j, p
        stat%code = 0
        lu = a
        do j = 1, n
            p = j - 1 + maxloc(abs(lu(j:n, j)), 1)
            if (.not. (abs(lu(p, j)) > 1.0e-300_dp)) then
                call set_error(stat, ERR_NUMERIC, 'platform: singular matrix')
                return
            end if
            if (p /= j) then
                t = lu(j, :); lu(j, :) = lu(p, :); lu(p, :) = t
                f = x(j); x(j) = x(p); x(p) = f
            end if
            piv = lu(j, j)
            do i = j + 1, n
                f = lu(i, j)/piv
                lu(i, j:n) = lu(i, j:n) - f*lu(j, j:n)
                x(i) = x(i) - f*x(j)
            end do
        end do
        do i = n, 1, -1
            x(i) = (x(i) - dot_product(lu(i, i + 1:n), x(i + 1:n)))/lu(i, i)
        end do
    end subroutine solve_sym

    !> The small oscillations about the rest pose (pl%q_ref, rest_pose first): K = d2V/dq_F2,
    !! M the generalized inertia there, omega^2 the eigenvalues of M^-1 K (ascending; < 0:
    !! unstable) and the mode shapes in q_F.
    subroutine linearise(pl, md, stat)
        type(platform_t), intent(in) :: pl
        type(platform_modes_t), intent(out) :: md
        type(status_t), intent(out) :: stat
        type(platform_kin_t) :: k
        real(dp) :: y(8), f(4), l(4, 4), a(4, 4), w(4), z(4, 4), linv(4, 4)
        integer :: nf, c
        nf = pl%nf
        md%nf = nf
        y = 0.0_dp
        y(1:nf) = pl%q_ref(pl%free(1:nf))
        call pose_of_state(pl, y(1:2*nf), k, stat)
        if (stat%code /= 0) return
        call kane_terms(pl, k, md%mass(1:nf, 1:nf), f(1:nf))
        call potential_hessian(pl, y(1:nf), md%stiffness(1:nf, 1:nf), stat)
        if (stat%code /= 0) return
        l(1:nf, 1:nf) = md%mass(1:nf, 1:nf)
        call la_small_chol(nf, l(1:nf, 1:nf), stat)
        if (stat%code /= 0) return
        ! L^-1 by columns, then A = L^-1 K L^-T
        linv = 0.0_dp
        do c = 1, nf
            linv(c, c) = 1.0_dp
            call lower_solve(nf, l(1:nf, 1:nf), linv(1:nf, c))
        end do
        a(1:nf, 1:nf) = matmul(linv(1:nf, 1:nf), matmul(md%stiffness(1:nf, 1:nf), &
                                                        transpose(linv(1:nf, 1:nf))))
        a(1:nf, 1:nf) = 0.5_dp*(a(1:nf, 1:nf) + transpose(a(1:nf, 1:nf)))
        call la_syev(a(1:nf, 1:nf), w(1:nf), z(1:nf, 1:nf), stat)
        if (stat%code /= 0) return
        md%omega2(1:nf) = w(1:nf)
        md%shapes(1:nf, 1:nf) = matmul(transpose(linv(1:nf, 1:nf)), z(1:nf, 1:nf))
    end subroutine linearise

    !> b = L^-1 b for a lower triangular L (the lower triangle of l).
    pure subroutine lower_solve(n, l, b)
        integer, intent(in) :: n
        real(dp), intent(in) :: l(n, n)
        real(dp), intent(inout) :: b(n)
        integer :: i
        do i = 1, n
            b(i) = (b(i) - dot_product(l(i, 1:i - 1), b(1:i - 1)))/l(i, i)
        end do
    end subroutine lower_solve

    !> The start: from the rest pose (rest_pose first) the body turned by `amplitude` about
    !! the vertical through its mass centre (or through `centre`, a horizontal point in N),
    !! moved by `sway` (horizontal, in N) and, for n = 2, swung by `tilt` about the line of
    !! its two body points; the dependent coordinates solved from the cables (Newton, the
    !! homotopy when Newton fails); released at rest.  y0 = (q_F, 0).
    subroutine platform_start(pl, amplitude, y0, stat, sway, centre, tilt)
        type(platform_t), intent(in) :: pl
        real(dp), intent(in) :: amplitude       !! turn about the vertical (rad)
        real(dp), intent(out) :: y0(:)          !! (2 nf)
        type(status_t), intent(out) :: stat
        real(dp), intent(in), optional :: sway(2)   !! horizontal move of the body
        real(dp), intent(in), optional :: centre(2) !! the vertical turned about
        real(dp), intent(in), optional :: tilt      !! n = 2: swing about the body points' line
        real(dp) :: q(6), r(3, 3), c(2), u(2), lm(3), ca, sa
        integer :: nf
        nf = pl%nf
        y0 = 0.0_dp
        q = pl%q_ref
        r = rotation(q(4), q(5), q(6))
        c = q(1:2) + matmul(r(1:2, :), pl%cg)
        if (present(centre)) c = centre
        ca = cos(amplitude)
        sa = sin(amplitude)
        u = q(1:2) - c
        q(1:2) = c + [ca*u(1) - sa*u(2), sa*u(1) + ca*u(2)]
        q(QPSI) = q(QPSI) + amplitude
        if (present(sway)) q(1:2) = q(1:2) + sway
        if (present(tilt) .and. pl%nd == 2) q(pl%free(4)) = q(pl%free(4)) + tilt
        lm(1:pl%nd) = pl%length(pl%master(1:pl%nd))
        call solve_pose(pl, q, lm(1:pl%nd), stat, from_ref=.true.)
        if (stat%code /= 0) then
            stat%code = ERR_DECK
            stat%msg = 'platform start amplitude = '//fixed(amplitude*180.0_dp/pi, 4)// &
                       ' deg: the cables cannot hold the body there; lower the amplitude '// &
                       'or the sway'
            return
        end if
        y0(1:nf) = q(pl%free(1:nf))
    end subroutine platform_start

    !> The smallest eigenvalue of M^-1 K at the rest pose of pl with its mass centre at
    !! depth `depth` (ok = .false. when no rest pose is found there).
    subroutine stability_at(pl, depth, zbar, lam, ok)
        type(platform_t), intent(in) :: pl
        real(dp), intent(in) :: depth, zbar
        real(dp), intent(out) :: lam
        logical, intent(out) :: ok
        type(platform_t) :: pd
        type(platform_modes_t) :: md
        type(status_t) :: st
        pd = pl
        pd%cg(3) = zbar - depth
        lam = -huge(1.0_dp)
        ok = .false.
        call rest_pose(pd, st)
        if (st%code /= 0) return
        call linearise(pd, md, st)
        if (st%code /= 0) return
        lam = md%omega2(1)
        ok = .true.
    end subroutine stability_at

    !> The tipping height: the cg_depth (below the plane of the attachments; < 0 above) at
    !! which the rest pose turns unstable, the rest of the rig as it is (the smallest
    !! eigenvalue of the linearised model, M^-1 K, through 0, located by bisection with the
    !! rest pose found again at each depth).  found = .false. when the body stays stable up
    !! to 1000 times the rig's size above the attachments (e.g. parallel cables, n = 3).
    subroutine tipping_depth(pl, depth, found, stat)
        type(platform_t), intent(in) :: pl      !! prepared (platform_prepare)
        real(dp), intent(out) :: depth          !! the tipping cg_depth
        logical, intent(out) :: found
        type(status_t), intent(out) :: stat
        real(dp) :: zbar, d0, dstable, dunstable, lam, step, dm
        logical :: ok
        integer :: i
        stat%code = 0
        found = .false.
        zbar = sum(pl%body(3, 1:pl%n))/pl%n
        d0 = zbar - pl%cg(3)
        depth = -huge(1.0_dp)
        call stability_at(pl, d0, zbar, lam, ok)
        step = 0.25_dp*pl%lscale
        if (ok .and. lam > 0.0_dp) then
            ! stable here: go up until it is not
            dstable = d0
            dunstable = d0
            do i = 1, 60
                dunstable = d0 - step
                call stability_at(pl, dunstable, zbar, lam, ok)
                if (.not. (ok .and. lam > 0.0_dp)) exit
                dstable = dunstable
                step = 2.0_dp*step
                if (step > 1000.0_dp*pl%lscale) return
            end do
        else
            ! unstable here: go down until it is stable
            dunstable = d0
            dstable = d0
            do i = 1, 60
                dstable = d0 + step
                call stability_at(pl, dstable, zbar, lam, ok)
                if (ok .and. lam > 0.0_dp) exit
                dunstable = dstable
                step = 2.0_dp*step
                if (step > 1000.0_dp*pl%lscale) then
                    call set_error(stat, ERR_DECK, 'platform: no stable rest pose at any '// &
                                   'cg_depth')
                    return
                end if
            end do
        end if
        do i = 1, 200
            dm = 0.5_dp*(dstable + dunstable)
            if (abs(dstable - dunstable) <= 1.0e-12_dp*pl%lscale) exit
            call stability_at(pl, dm, zbar, lam, ok)
            if (ok .and. lam > 0.0_dp) then
                dstable = dm
            else
                dunstable = dm
            end if
        end do
        depth = 0.5_dp*(dstable + dunstable)
        found = .true.
    end subroutine tipping_depth

    !> Check a rig for the inextensible model and find its rest pose: the inputs and the
    !! chart (platform_prepare), n <= 3, a rest pose, every cable hanging down from its
    !! support and taut there, and the rest pose stable (else the tipping height is named).
    !! One line in stat (ERR_DECK).
    subroutine check_platform(pl, stat)
        type(platform_t), intent(inout) :: pl
        type(status_t), intent(out) :: stat
        type(platform_motion_t) :: mo
        type(platform_modes_t) :: md
        real(dp) :: y(8), depth, zbar, r(3, 3)
        logical :: found
        integer :: i, nf
        call platform_prepare(pl, stat)
        if (stat%code /= 0) return
        if (pl%n > 3) then
            call set_error(stat, ERR_DECK, 'platform cables = '//itoa(pl%n)//': with '// &
                           'inextensible cables n >= 4 is statically indeterminate; use '// &
                           'the elastic-cable model')
            return
        end if
        call rest_pose(pl, stat)
        if (stat%code /= 0) return
        nf = pl%nf
        y = 0.0_dp
        y(1:nf) = pl%q_ref(pl%free(1:nf))
        call platform_evaluate(pl, y(1:2*nf), mo, stat)
        if (stat%code /= 0) then
            stat%code = ERR_DECK
            return
        end if
        r = rotation(mo%q(4), mo%q(5), mo%q(6))
        do i = 1, pl%n
            if (.not. (mo%q(3) + dot_product(r(3, :), pl%body(:, i)) < pl%support(3, i))) then
                call set_error(stat, ERR_DECK, 'platform lengths('//itoa(i)//') = '// &
                               sci(pl%length(i))//': its body point would hang above its '// &
                               'support point; the cable is shorter than the height '// &
                               'difference it must span')
                return
            end if
        end do
        do i = 1, pl%nd
            if (.not. (mo%tension(i) > 0.0_dp)) then
                call set_error(stat, ERR_DECK, 'platform: cable '//itoa(pl%master(i))// &
                               ' is slack at rest (tension '//sci(mo%tension(i))//'): the '// &
                               'mass centre lies outside the attachments as the cables see '// &
                               'them; move cg_offset inwards')
                return
            end if
        end do
        call linearise(pl, md, stat)
        if (stat%code /= 0) return
        if (.not. (md%omega2(1) > 0.0_dp)) then
            zbar = sum(pl%body(3, 1:pl%n))/pl%n
            call tipping_depth(pl, depth, found, stat)
            if (stat%code /= 0) return
            if (found) then
                call set_error(stat, ERR_DECK, 'platform cg_depth = '//sci(zbar - pl%cg(3))// &
                               ': the body tips over (its rest pose is unstable) with the '// &
                               'mass centre above cg_depth = '//sci(depth)//'; lower it')
            else
                call set_error(stat, ERR_DECK, 'platform: the rest pose is unstable')
            end if
        end if
    end subroutine check_platform

end module platform_model
