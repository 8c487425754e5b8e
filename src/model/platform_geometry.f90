!> Geometry and kinematics of a rigid body hung by n >= 2 cables (the multifilar platform):
!! the rig (platform_t), the chart of generalized coordinates in which the cable
!! constraints are solved (platform_prepare, solve_pose), and the partial velocities and
!! convective accelerations of the body for Kane's equations (platform_kinematics).
!! doc/theory.md, "The multifilar platform", derives what is written here.
!!
!! Frames and units.  The support frame N is inertial with n3 up; gravity is -g n3.  The
!! body frame B is fixed in the body; with the body level (hanging as the rig is drawn) its
!! z axis is up.  Cable i joins the support point S_i (N components) to the body point p_i
!! (B components) and has length l_i.  The units are any consistent set (SI, or scaled:
!! platform_scaled gives m = g = 1 and lengths over a reference length); time is in the
!! unit that g implies.
!!
!! The pose.  q = (x, y, z, psi, theta, phi): the position r of the body frame's origin in N
!! and the orientation R = Rz(psi) Ry(theta) Rx(phi) (B components to N components): yaw
!! psi about the vertical, then pitch theta and roll phi, which tilt the body.  The angular
!! velocity is omega = psi' n3 + theta' a2 + phi' a1 with a2 = Rz(psi) e2 and a1 = R e1
!! (the first column of R); the chart is singular only at theta = +-90 degrees (the body
!! turned on edge).  A body point is P = r + R p.
!!
!! The chart.  The constraints g_i = (|P_i - S_i|^2 - l_i^2)/2 = 0 of the m = min(n, 3)
!! master cables are solved for m dependent coordinates: (z, theta, phi) for n >= 3; for
!! n = 2, z and the one of theta, phi that the line of the two body points tilts with (the
!! other, the swing about that line, stays free).  The free coordinates are the rest:
!! (x, y, psi) for n >= 3, (x, y, psi, phi or theta) for n = 2.  The solve is Newton's
!! method from the reference pose (the rest pose once known), with the paper's homotopy
!! (eq. (44) generalised: G(q(xi)) = (1 - xi) G(q(0))) when Newton does not converge.  The
!! chart is regular where the constraint Jacobian A_D = dg/dq_D is: cables not horizontal,
!! attachments not collinear as the cables see them; that is where a hanging body moves.
!! For n >= 4 the masters are the three cables whose A_D is best conditioned at the
!! reference pose; the others follow the pose (elastic cables, module platform_elastic).
!!
!! Generalized speeds.  The free coordinates' rates, and for elastic cables the master
!! cables' length rates: Qdot = (q_F', s_1', ..., s_m').  The dependent rates follow from
!! the constraints, q_D' = Gamma Qdot, Gamma = -A_D^-1 [A_F, -diag(l)], and the partial
!! velocities of the body's origin and its partial angular velocities (vv, vw) are the
!! columns of E [I; Gamma] (E maps q' to (v_r, omega)).  The accelerations at Qddot = 0
!! (a0, al0) come from the twice-differentiated constraints.
module platform_geometry
    use kinds, only: dp, pi
    use status, only: status_t, set_error, ERR_DECK, ERR_MODEL
    use text, only: sci, itoa
    use vectors, only: cross
    implicit none
    private

    !> Most cables of one platform.
    integer, parameter, public :: PLATFORM_NMAX = 12
    !> Indices of the pose q = (x, y, z, psi, theta, phi).
    integer, parameter, public :: QX = 1, QY = 2, QZ = 3, QPSI = 4, QTHETA = 5, QPHI = 6
    !> Below this regularity of the chart (|det A_D| over the product of its rows' norms)
    !! the constraints are not solved: attachments collinear as the cables see them,
    !! cables horizontal.
    real(dp), parameter, public :: CHART_MIN_QUALITY = 1.0e-6_dp

    !> The rig: cables, body, and the chart (set by platform_prepare).
    type, public :: platform_t
        integer :: n = 3                                !! number of cables, 2 ... PLATFORM_NMAX
        real(dp) :: support(3, PLATFORM_NMAX) = 0.0_dp  !! S_i in N (support frame, z up)
        real(dp) :: body(3, PLATFORM_NMAX) = 0.0_dp     !! p_i in B (body frame, z up when level)
        real(dp) :: length(PLATFORM_NMAX) = 0.0_dp      !! l_i
        real(dp) :: mass = 1.0_dp                       !! m
        real(dp) :: gravity = 1.0_dp                    !! g
        real(dp) :: cg(3) = 0.0_dp                      !! the mass centre in B
        real(dp) :: inertia(3, 3) = 0.0_dp              !! inertia tensor about the mass
                                                        !! centre in B
        !> Damping about the vertical: the torque on the body is -(c_v W + c_q |W| W) n3,
        !! W = omega . n3 (0: undamped)
        real(dp) :: c_v = 0.0_dp, c_q = 0.0_dp
        ! -- the chart (platform_prepare) --
        logical :: ready = .false.                      !! platform_prepare succeeded
        integer :: nd = 0                               !! dependent coordinates = masters
        integer :: nf = 0                               !! free coordinates, 6 - nd
        integer :: dep(3) = 0                           !! their indices in q
        integer :: free(4) = 0                          !! the free ones' indices in q
        integer :: master(3) = 0                        !! the cables solved for q(dep)
        real(dp) :: q_ref(6) = 0.0_dp                   !! reference pose (guess of solve_pose;
                                                        !! set_reference)
        real(dp) :: trig_ref(4) = [0.0_dp, 1.0_dp, 0.0_dp, 1.0_dp]  !! sin, cos of its theta, phi
        real(dp) :: lscale = 1.0_dp                     !! length scale (tolerances)
    end type platform_t

    !> The kinematics at one state: pose, points, and what Kane's equations need.
    type, public :: platform_kin_t
        real(dp) :: q(6), qd(6)                 !! pose and its rates
        real(dp) :: rot(3, 3)                   !! R (B components to N)
        real(dp) :: a1(3), a2(3)                !! the axes of phi' and theta'
        real(dp) :: rho(3, PLATFORM_NMAX)       !! R p_i
        real(dp) :: d(3, PLATFORM_NMAX)         !! P_i - S_i (the cables)
        real(dp) :: pd(3, PLATFORM_NMAX)        !! dP_i/dt
        real(dp) :: rhoc(3)                     !! R c (mass centre from the origin)
        real(dp) :: vr(3), omega(3)             !! origin's velocity, angular velocity
        real(dp) :: adinv(3, 3)                 !! A_D^-1 (nd x nd, zeros beyond)
        logical :: singular                     !! A_D singular (the rest is not set)
        integer :: ns                           !! generalized speeds
        real(dp) :: gam(3, 6)                   !! q_D' = Gamma Qdot
        real(dp) :: vv(3, 6), vw(3, 6)          !! partial velocities of the origin,
                                                !! partial angular velocities
        real(dp) :: a0(3), al0(3)               !! origin's acceleration and angular
                                                !! acceleration at Qddot = 0
        ! (no default values: an intent(out) argument of this type is not filled on entry)
    end type platform_kin_t

    public :: regular_platform, general_platform, platform_prepare, platform_scaled
    public :: platform_inertia
    public :: rotation, pose_points, solve_pose, platform_kinematics, chart_quality
    public :: master_residual, level_pose, inertia_ok, set_reference, guess_pose, keep_guess

    !> The last solved pose of a run and its derivatives: the first-order guess of the next
    !! one, q_D = q_D,last + Gamma (u - u_last) (u: the generalized coordinates, free and
    !! stretches), so that Newton starts a step's length away from the solution.
    type, public :: pose_guess_t
        logical :: valid = .false.
        integer :: nu = 0                       !! generalized coordinates
        real(dp) :: q(6) = 0.0_dp               !! the last pose
        real(dp) :: u(6) = 0.0_dp               !! its generalized coordinates
        real(dp) :: gam(3, 6) = 0.0_dp          !! dq_D/du there
    end type pose_guess_t

    !> Newton's most iterations in solve_pose before the homotopy.
    integer, parameter :: NEWTON_MAX = 16
    !> RK4 steps of the homotopy.
    integer, parameter :: HOMOTOPY_STEPS = 32

contains

    ! ------------------------------------------------------------------------------------
    ! Construction
    ! ------------------------------------------------------------------------------------

    !> A regular polygon: support points S_i = R (cos a_i, sin a_i, 0), body points
    !! p_i = R' (cos a_i, sin a_i, 0), a_i = 2 pi (i - 1)/n, every cable of length l; the
    !! mass centre at (cg_offset(1), cg_offset(2), -cg_depth) in B (cg_depth > 0 below the
    !! plane of the attachments, < 0 above).  Not checked here (platform_prepare).
    pure function regular_platform(n, radius, radius_prime, l, mass, inertia, cg_offset, &
                                   cg_depth, gravity) result(pl)
        integer, intent(in) :: n                !! cables
        real(dp), intent(in) :: radius          !! R, of the support points
        real(dp), intent(in) :: radius_prime    !! R', of the body points
        real(dp), intent(in) :: l               !! length of every cable
        real(dp), intent(in) :: mass            !! m
        real(dp), intent(in) :: inertia(3, 3)   !! about the mass centre, in B
        real(dp), intent(in) :: cg_offset(2)    !! horizontal offset of the mass centre
        real(dp), intent(in) :: cg_depth        !! depth below the attachments' plane
        real(dp), intent(in) :: gravity         !! g
        type(platform_t) :: pl
        real(dp) :: sup(3, max(n, 1)), bod(3, max(n, 1)), a
        integer :: i
        do i = 1, n
            a = 2.0_dp*pi*(i - 1)/n
            sup(:, i) = radius*[cos(a), sin(a), 0.0_dp]
            bod(:, i) = radius_prime*[cos(a), sin(a), 0.0_dp]
        end do
        pl = general_platform(n, sup, bod, [(l, i = 1, n)], mass, inertia, cg_offset, &
                              cg_depth, gravity)
    end function regular_platform

    !> The inertia tensor about the mass centre in the body's frame (x, y, z) from the
    !! principal moments and btilde (rows: the principal axes in (z, x, y)): the axes
    !! (e1, e2, e3) = (z, x, y) of the body's frame, e1 vertical when the body hangs level.
    pure function platform_inertia(inertia, btilde) result(jb)
        real(dp), intent(in) :: inertia(3)      !! principal moments
        real(dp), intent(in) :: btilde(3, 3)    !! row i: axis i in (z, x, y)
        real(dp) :: jb(3, 3)
        real(dp) :: je(3, 3)
        integer, parameter :: perm(3) = [2, 3, 1]     ! x, y, z are e2, e3, e1
        integer :: a, b, k
        ! J_E = btilde^T diag(inertia) btilde, term by term
        do b = 1, 3
            do a = 1, 3
                je(a, b) = 0.0_dp
                do k = 1, 3
                    je(a, b) = je(a, b) + btilde(k, a)*inertia(k)*btilde(k, b)
                end do
            end do
        end do
        do b = 1, 3
            do a = 1, 3
                jb(a, b) = je(perm(a), perm(b))
            end do
        end do
        jb = 0.5_dp*(jb + transpose(jb))
    end function platform_inertia

    !> Any n cables: support points (N), body points (B), lengths; the mass centre at
    !! (cg_offset, zbar - cg_depth) in B, zbar the mean height of the body points in B.
    !! Not checked here (platform_prepare).
    pure function general_platform(n, support, body, lengths, mass, inertia, cg_offset, &
                                   cg_depth, gravity) result(pl)
        integer, intent(in) :: n
        real(dp), intent(in) :: support(:, :)   !! (3, n)
        real(dp), intent(in) :: body(:, :)      !! (3, n)
        real(dp), intent(in) :: lengths(:)      !! (n)
        real(dp), intent(in) :: mass, inertia(3, 3), cg_offset(2), cg_depth, gravity
        type(platform_t) :: pl
        integer :: nn
        nn = max(0, min(n, PLATFORM_NMAX, size(lengths), size(support, 2), size(body, 2)))
        pl%n = n
        pl%support(:, 1:nn) = support(:, 1:nn)
        pl%body(:, 1:nn) = body(:, 1:nn)
        pl%length(1:nn) = lengths(1:nn)
        pl%mass = mass
        pl%gravity = gravity
        pl%inertia = inertia
        pl%cg(1:2) = cg_offset
        pl%cg(3) = -cg_depth
        if (nn > 0) pl%cg(3) = sum(body(3, 1:nn))/nn - cg_depth
    end function general_platform

    !> The platform in scaled units: m = g = 1, lengths over `lref`; time then in units of
    !! sqrt(lref/g).  Damping c_v in m sqrt(g lref) lref units, c_q in m lref^2.
    pure function platform_scaled(pl, lref) result(ps)
        type(platform_t), intent(in) :: pl
        real(dp), intent(in) :: lref            !! the reference length (> 0)
        type(platform_t) :: ps
        ps = pl
        ps%support = pl%support/lref
        ps%body = pl%body/lref
        ps%length = pl%length/lref
        ps%cg = pl%cg/lref
        ps%inertia = pl%inertia/(pl%mass*lref**2)
        ps%mass = 1.0_dp
        ps%gravity = 1.0_dp
        ps%c_v = pl%c_v/(pl%mass*lref*sqrt(pl%gravity*lref))
        ps%c_q = pl%c_q/(pl%mass*lref**2)
        ps%q_ref(1:3) = pl%q_ref(1:3)/lref
        ps%lscale = pl%lscale/lref
    end function platform_scaled

    !> Check the rig's inputs and set up its chart: the dependent coordinates, the master
    !! cables and the reference pose (the body level below the supports, turned by 0).
    !! One line in stat (ERR_DECK) names the input and what is allowed.
    subroutine platform_prepare(pl, stat)
        type(platform_t), intent(inout) :: pl
        type(status_t), intent(out) :: stat
        real(dp) :: size_b, size_s, best, qual, q(6)
        integer :: i, j, k, n, triple(3)
        character(len=:), allocatable :: why
        stat%code = 0
        pl%ready = .false.
        n = pl%n
        if (n < 2 .or. n > PLATFORM_NMAX) then
            call set_error(stat, ERR_DECK, 'platform cables = '//itoa(n)//': must be 2 ... '// &
                           itoa(PLATFORM_NMAX))
            return
        end if
        if (.not. (pl%mass > 0.0_dp .and. pl%mass < huge(1.0_dp))) then
            call set_error(stat, ERR_DECK, 'platform mass = '//sci(pl%mass)//': must be > 0')
            return
        end if
        if (.not. (pl%gravity > 0.0_dp .and. pl%gravity < huge(1.0_dp))) then
            call set_error(stat, ERR_DECK, 'platform gravity = '//sci(pl%gravity)// &
                           ': must be > 0')
            return
        end if
        do i = 1, n
            if (.not. (pl%length(i) > 0.0_dp .and. pl%length(i) < huge(1.0_dp))) then
                call set_error(stat, ERR_DECK, 'platform lengths('//itoa(i)//') = '// &
                               sci(pl%length(i))//': must be > 0')
                return
            end if
        end do
        if (.not. all(abs(pl%support(:, 1:n)) < huge(1.0_dp)) .or. &
            .not. all(abs(pl%body(:, 1:n)) < huge(1.0_dp)) .or. &
            .not. all(abs(pl%cg) < huge(1.0_dp))) then
            call set_error(stat, ERR_DECK, 'platform support_points, body_points, cg: '// &
                           'must be finite')
            return
        end if
        call inertia_ok(pl%inertia, why)
        if (len(why) > 0) then
            call set_error(stat, ERR_DECK, 'platform inertia: '//why)
            return
        end if
        size_b = maxval(abs(pl%body(:, 1:n)))
        size_s = maxval(abs(pl%support(:, 1:n)))
        pl%lscale = max(maxval(pl%length(1:n)), size_b, size_s)
        ! distinct points; for n >= 3 not all on one line
        do i = 1, n
            do j = i + 1, n
                if (norm2(pl%body(:, i) - pl%body(:, j)) <= 1.0e-9_dp*pl%lscale) then
                    call set_error(stat, ERR_DECK, 'platform body_points '//itoa(i)//' and '// &
                                   itoa(j)//' coincide: the attachments must be distinct')
                    return
                end if
                if (norm2(pl%support(:, i) - pl%support(:, j)) <= 1.0e-9_dp*pl%lscale) then
                    call set_error(stat, ERR_DECK, 'platform support_points '//itoa(i)// &
                                   ' and '//itoa(j)//' coincide: the attachments must be '// &
                                   'distinct')
                    return
                end if
            end do
        end do
        if (n >= 3) then
            if (collinear(pl%body, n, pl%lscale)) then
                call set_error(stat, ERR_DECK, 'platform body_points: the '//itoa(n)// &
                               ' attachments on the body are collinear; they must span a plane')
                return
            end if
            if (collinear(pl%support, n, pl%lscale)) then
                call set_error(stat, ERR_DECK, 'platform support_points: the '//itoa(n)// &
                               ' attachments on the support are collinear; they must span '// &
                               'a plane')
                return
            end if
        end if
        ! a cable must reach below every other support: l_j + |p_i - p_j| > S_jz - S_iz
        do i = 1, n
            do j = 1, n
                if (i == j) cycle
                if (pl%support(3, j) - pl%support(3, i) >= &
                    pl%length(j) + norm2(pl%body(:, i) - pl%body(:, j))) then
                    call set_error(stat, ERR_DECK, 'platform lengths('//itoa(j)//') = '// &
                                   sci(pl%length(j))//': shorter than the height '// &
                                   'difference '//sci(pl%support(3, j) - pl%support(3, i))// &
                                   ' between support points '//itoa(j)//' and '//itoa(i)// &
                                   ' less the body''s span '// &
                                   sci(norm2(pl%body(:, i) - pl%body(:, j)))// &
                                   ': the body cannot hang below support point '//itoa(i))
                    return
                end if
            end do
        end do
        ! the reference pose: level, below the supports
        call level_pose(pl, q, stat)
        if (stat%code /= 0) return
        call set_reference(pl, q)
        ! the chart: dependent coordinates and master cables
        pl%nd = min(n, 3)
        pl%nf = 6 - pl%nd
        if (n == 2) then
            pl%master(1:2) = [1, 2]
            pl%dep(1:2) = [QZ, QTHETA]
            qual = chart_quality(pl, pl%q_ref)
            pl%dep(1:2) = [QZ, QPHI]
            if (chart_quality(pl, pl%q_ref) < qual) pl%dep(1:2) = [QZ, QTHETA]
            pl%dep(3) = 0
        else
            pl%dep = [QZ, QTHETA, QPHI]
            pl%master = [1, 2, 3]
            best = -1.0_dp
            triple = [1, 2, 3]
            do i = 1, n
                do j = i + 1, n
                    do k = j + 1, n
                        pl%master = [i, j, k]
                        qual = chart_quality(pl, pl%q_ref)
                        if (qual > best*(1.0_dp + 1.0e-9_dp)) then
                            best = qual
                            triple = [i, j, k]
                        end if
                    end do
                end do
            end do
            pl%master = triple
        end if
        k = 0
        pl%free = 0
        do i = 1, 6
            if (any(pl%dep(1:pl%nd) == i)) cycle
            k = k + 1
            pl%free(k) = i
        end do
        if (chart_quality(pl, pl%q_ref) < CHART_MIN_QUALITY) then
            call set_error(stat, ERR_DECK, 'platform: the cables cannot hold the body in '// &
                           'a regular pose (the attachments are collinear as the cables see '// &
                           'them, or the cables are horizontal)')
            return
        end if
        pl%ready = .true.
    end subroutine platform_prepare

    !> Whether the n points are on one line (within 1e-9 of the scale).
    pure logical function collinear(pts, n, scale)
        real(dp), intent(in) :: pts(:, :), scale
        integer, intent(in) :: n
        real(dp) :: u(3), w(3), a
        integer :: j, k
        collinear = .true.
        do j = 2, n
            u = pts(:, j) - pts(:, 1)
            do k = j + 1, n
                w = pts(:, k) - pts(:, 1)
                a = norm2(cross(u, w))
                if (a > 1.0e-9_dp*scale**2) then
                    collinear = .false.
                    return
                end if
            end do
        end do
    end function collinear

    !> An inertia tensor's check: why is '' when it is symmetric with positive principal
    !! moments that satisfy the triangle inequalities (I_i <= I_j + I_k), else what is wrong.
    pure subroutine inertia_ok(a, why)
        real(dp), intent(in) :: a(3, 3)
        character(len=:), allocatable, intent(out) :: why
        real(dp) :: ev(3), sc
        why = ''
        if (.not. all(abs(a) < huge(1.0_dp))) then
            why = 'must be finite'
            return
        end if
        sc = maxval(abs(a))
        if (abs(a(1, 2) - a(2, 1)) > 1.0e-12_dp*sc .or. abs(a(1, 3) - a(3, 1)) > &
            1.0e-12_dp*sc .or. abs(a(2, 3) - a(3, 2)) > 1.0e-12_dp*sc) then
            why = 'must be symmetric'
            return
        end if
        ev = sym3_eigenvalues(a)
        if (.not. (ev(1) > 0.0_dp)) then
            why = 'the principal moments must be > 0 (smallest '//sci(ev(1))//')'
        else if (ev(3) > (ev(1) + ev(2))*(1.0_dp + 1.0e-12_dp)) then
            why = 'the principal moments '//sci(ev(1))//', '//sci(ev(2))//', '//sci(ev(3))// &
                  ' break the triangle inequality (largest <= sum of the others)'
        end if
    end subroutine inertia_ok

    !> Eigenvalues of a symmetric 3 x 3 matrix, ascending (the trigonometric solution of the
    !! characteristic cubic).
    pure function sym3_eigenvalues(a) result(ev)
        real(dp), intent(in) :: a(3, 3)
        real(dp) :: ev(3)
        real(dp) :: p1, q, p2, p, b(3, 3), r, phi, t
        integer :: i
        p1 = a(1, 2)**2 + a(1, 3)**2 + a(2, 3)**2
        q = (a(1, 1) + a(2, 2) + a(3, 3))/3.0_dp
        p2 = (a(1, 1) - q)**2 + (a(2, 2) - q)**2 + (a(3, 3) - q)**2 + 2.0_dp*p1
        p = sqrt(p2/6.0_dp)
        if (p == 0.0_dp) then
            ev = q
            return
        end if
        b = a
        do i = 1, 3
            b(i, i) = a(i, i) - q
        end do
        b = b/p
        r = 0.5_dp*(b(1, 1)*(b(2, 2)*b(3, 3) - b(2, 3)*b(3, 2)) &
                    - b(1, 2)*(b(2, 1)*b(3, 3) - b(2, 3)*b(3, 1)) &
                    + b(1, 3)*(b(2, 1)*b(3, 2) - b(2, 2)*b(3, 1)))
        r = max(-1.0_dp, min(1.0_dp, r))
        phi = acos(r)/3.0_dp
        ev(3) = q + 2.0_dp*p*cos(phi)
        ev(1) = q + 2.0_dp*p*cos(phi + 2.0_dp*pi/3.0_dp)
        ev(2) = 3.0_dp*q - ev(1) - ev(3)
        if (ev(2) < ev(1)) then
            t = ev(1); ev(1) = ev(2); ev(2) = t
        end if
        if (ev(3) < ev(2)) then
            t = ev(2); ev(2) = ev(3); ev(3) = t
        end if
    end function sym3_eigenvalues

    !> The level pose below the supports: theta = phi = 0, the body turned by psi and moved
    !! so that its points lie under the support points as nearly as a turn and a shift can
    !! put them (least squares in the horizontal plane), and z where the cables reach on
    !! average.  ERR_DECK when a cable cannot reach its support with the body there.
    subroutine level_pose(pl, q, stat)
        type(platform_t), intent(in) :: pl
        real(dp), intent(out) :: q(6)
        type(status_t), intent(out) :: stat
        real(dp) :: h2, zsum, sbar(2), pbar(2), sxy, sdot, u(2), w(2), c, s, pr(2)
        integer :: i, n
        stat%code = 0
        n = pl%n
        q = 0.0_dp
        sbar = [sum(pl%support(1, 1:n)), sum(pl%support(2, 1:n))]/n
        pbar = [sum(pl%body(1, 1:n)), sum(pl%body(2, 1:n))]/n
        sxy = 0.0_dp
        sdot = 0.0_dp
        do i = 1, n
            u = pl%body(1:2, i) - pbar
            w = pl%support(1:2, i) - sbar
            sxy = sxy + u(1)*w(2) - u(2)*w(1)
            sdot = sdot + u(1)*w(1) + u(2)*w(2)
        end do
        if (abs(sxy) > 1.0e-12_dp*abs(sdot)) q(QPSI) = atan2(sxy, sdot)
        c = cos(q(QPSI))
        s = sin(q(QPSI))
        q(1:2) = sbar - [c*pbar(1) - s*pbar(2), s*pbar(1) + c*pbar(2)]
        zsum = 0.0_dp
        do i = 1, n
            pr = [c*pl%body(1, i) - s*pl%body(2, i), s*pl%body(1, i) + c*pl%body(2, i)]
            h2 = (q(1) + pr(1) - pl%support(1, i))**2 + (q(2) + pr(2) - pl%support(2, i))**2
            if (.not. (h2 < pl%length(i)**2)) then
                call set_error(stat, ERR_DECK, 'platform lengths('//itoa(i)//') = '// &
                               sci(pl%length(i))//': shorter than the horizontal distance '// &
                               sci(sqrt(h2))//' from its support point to its body point '// &
                               'with the body level below the supports; lengthen the cable')
                return
            end if
            zsum = zsum + pl%support(3, i) - pl%body(3, i) - sqrt(pl%length(i)**2 - h2)
        end do
        q(3) = zsum/n
    end subroutine level_pose

    ! ------------------------------------------------------------------------------------
    ! The pose
    ! ------------------------------------------------------------------------------------

    !> R = Rz(psi) Ry(theta) Rx(phi).
    pure function rotation(psi, theta, phi) result(r)
        real(dp), intent(in) :: psi, theta, phi
        real(dp) :: r(3, 3)
        call rot_trig(sin(psi), cos(psi), sin(theta), cos(theta), sin(phi), cos(phi), r)
    end function rotation

    !> R from the sines and cosines of psi, theta, phi.
    pure subroutine rot_trig(sp, cp, st, ct, sf, cf, r)
        real(dp), intent(in) :: sp, cp, st, ct, sf, cf
        real(dp), intent(out) :: r(3, 3)
        r(1, 1) = cp*ct
        r(2, 1) = sp*ct
        r(3, 1) = -st
        r(1, 2) = cp*st*sf - sp*cf
        r(2, 2) = sp*st*sf + cp*cf
        r(3, 2) = ct*sf
        r(1, 3) = cp*st*cf + sp*sf
        r(2, 3) = sp*st*cf - cp*sf
        r(3, 3) = ct*cf
    end subroutine rot_trig

    !> The body points P_i and the mass centre in N at pose q.
    pure subroutine pose_points(pl, q, p, rc)
        type(platform_t), intent(in) :: pl
        real(dp), intent(in) :: q(6)
        real(dp), intent(out) :: p(3, pl%n)     !! P_i
        real(dp), intent(out) :: rc(3)          !! the mass centre
        real(dp) :: r(3, 3)
        integer :: i
        r = rotation(q(4), q(5), q(6))
        do i = 1, pl%n
            p(:, i) = q(1:3) + matmul(r, pl%body(:, i))
        end do
        rc = q(1:3) + matmul(r, pl%cg)
    end subroutine pose_points

    !> The master cables' constraint residuals g_i = (|P_i - S_i|^2 - l_i^2)/2 at pose q
    !! with the masters' lengths lm.
    pure function master_residual(pl, q, lm) result(g)
        type(platform_t), intent(in) :: pl
        real(dp), intent(in) :: q(6), lm(:)
        real(dp) :: g(pl%nd)
        real(dp) :: r(3, 3), d(3)
        integer :: j, i
        r = rotation(q(4), q(5), q(6))
        do j = 1, pl%nd
            i = pl%master(j)
            d = q(1:3) + matmul(r, pl%body(:, i)) - pl%support(:, i)
            g(j) = 0.5_dp*(dot_product(d, d) - lm(j)**2)
        end do
    end function master_residual

    !> The chart's regularity at pose q: |det A_D| over the product of the norms of A_D's
    !! rows (1 for orthogonal rows, 0 where the chart is singular).
    pure real(dp) function chart_quality(pl, q) result(qual)
        type(platform_t), intent(in) :: pl
        real(dp), intent(in) :: q(6)
        real(dp) :: r(3, 3), ad(3, 3), g(3), a2(3), rho(3), d(3)
        integer :: j
        r = rotation(q(4), q(5), q(6))
        a2 = [-sin(q(4)), cos(q(4)), 0.0_dp]
        ad = 0.0_dp
        do j = 1, pl%nd
            rho = matmul(r, pl%body(:, pl%master(j)))
            d = q(1:3) + rho - pl%support(:, pl%master(j))
            call constraint_row(pl, rho, d, r(:, 1), a2, ad(j, :), g(j))
        end do
        qual = quality_of(pl%nd, ad)
    end function chart_quality

    !> Row j of A_D (dg_j/dq_D) of a cable with R p = rho and P - S = d; g the residual's
    !! half square |d|^2/2 (the length not subtracted).
    pure subroutine constraint_row(pl, rho, d, a1, a2, row, g)
        type(platform_t), intent(in) :: pl
        real(dp), intent(in) :: rho(3), d(3), a1(3), a2(3)
        real(dp), intent(out) :: row(3), g
        real(dp) :: full(6)
        integer :: k
        full = full_row(rho, d, a1, a2)
        row = 0.0_dp
        do k = 1, pl%nd
            row(k) = full(pl%dep(k))
        end do
        g = 0.5_dp*(d(1)*d(1) + d(2)*d(2) + d(3)*d(3))
    end subroutine constraint_row

    !> dg/dq of a cable for all six coordinates: (d, (rho x d) . (n3, a2, a1)).
    pure function full_row(rho, d, a1, a2) result(row)
        real(dp), intent(in) :: rho(3), d(3), a1(3), a2(3)
        real(dp) :: row(6), m(3)
        m(1) = rho(2)*d(3) - rho(3)*d(2)
        m(2) = rho(3)*d(1) - rho(1)*d(3)
        m(3) = rho(1)*d(2) - rho(2)*d(1)
        row(1:3) = d
        row(4) = m(3)
        row(5) = m(1)*a2(1) + m(2)*a2(2)
        row(6) = m(1)*a1(1) + m(2)*a1(2) + m(3)*a1(3)
    end function full_row

    !> |det a| over the product of its rows' norms, a of order nd (2 or 3).
    pure real(dp) function quality_of(nd, a) result(qual)
        integer, intent(in) :: nd
        real(dp), intent(in) :: a(3, 3)
        real(dp) :: den
        if (nd == 2) then
            den = norm2(a(1, 1:2))*norm2(a(2, 1:2))
            qual = abs(a(1, 1)*a(2, 2) - a(1, 2)*a(2, 1))
        else
            den = norm2(a(1, :))*norm2(a(2, :))*norm2(a(3, :))
            qual = abs(det3(a))
        end if
        if (den > 0.0_dp) then
            qual = qual/den
        else
            qual = 0.0_dp
        end if
    end function quality_of

    pure real(dp) function det3(a)
        real(dp), intent(in) :: a(3, 3)
        det3 = a(1, 1)*(a(2, 2)*a(3, 3) - a(2, 3)*a(3, 2)) &
               - a(1, 2)*(a(2, 1)*a(3, 3) - a(2, 3)*a(3, 1)) &
               + a(1, 3)*(a(2, 1)*a(3, 2) - a(2, 2)*a(3, 1))
    end function det3

    !> The dependent coordinates q(dep) that satisfy the master cables' constraints with
    !! lengths lm, the free ones q(free) given: Newton's method from q(dep) as given; when
    !! it does not converge (or with `from_ref`), from the reference pose's, its height
    !! moved to where the masters reach; when Newton does not converge from there either,
    !! the homotopy G(q(xi)) = (1 - xi) G(q(0)) integrated from that start by classical
    !! Runge-Kutta, then Newton again.  ERR_MODEL when no
    !! solution is found.  tr returns the sines and cosines of the pose's angles (for
    !! platform_kinematics): Newton updates them by the addition formulas, so that an
    !! evaluation calls sin and cos for psi alone.
    pure subroutine solve_pose(pl, q, lm, stat, from_ref, iterations, tr, newton_limit)
        type(platform_t), intent(in) :: pl
        real(dp), intent(inout) :: q(6)         !! in: q(free) and a guess of q(dep); out: pose
        real(dp), intent(in) :: lm(:)           !! (nd) the master cables' lengths
        type(status_t), intent(out) :: stat
        logical, intent(in), optional :: from_ref   !! start from the reference pose
        integer, intent(out), optional :: iterations    !! Newton iterations taken
        real(dp), intent(out), optional :: tr(6)    !! sin, cos of psi, theta, phi at q
        integer, intent(in), optional :: newton_limit   !! Newton's most iterations before
                                                        !! the homotopy (default 16; tests)
        real(dp) :: q0(6), g0(3), t(6), k1(3), k2(3), k3(3), k4(3), h
        integer :: it, i, j, lim
        logical :: conv, ref
        stat%code = 0
        lim = NEWTON_MAX
        if (present(newton_limit)) lim = max(1, min(NEWTON_MAX, newton_limit))
        ref = .false.
        if (present(from_ref)) ref = from_ref
        t(1) = sin(q(QPSI))
        t(2) = cos(q(QPSI))
        if (present(iterations)) iterations = 0
        if (.not. ref) then
            ! from the guess given in q(dep)
            t(3:6) = [sin(q(QTHETA)), cos(q(QTHETA)), sin(q(QPHI)), cos(q(QPHI))]
            call newton(pl, lm, q, t, conv, it, lim)
            if (present(iterations)) iterations = it
            if (present(tr)) tr = t
            if (conv) return
        end if
        ! from the reference pose, its height where the masters reach
        do j = 1, pl%nd
            q(pl%dep(j)) = pl%q_ref(pl%dep(j))
        end do
        if (q(QTHETA) == pl%q_ref(QTHETA)) then
            t(3:4) = pl%trig_ref(1:2)
        else
            t(3:4) = [sin(q(QTHETA)), cos(q(QTHETA))]
        end if
        if (q(QPHI) == pl%q_ref(QPHI)) then
            t(5:6) = pl%trig_ref(3:4)
        else
            t(5:6) = [sin(q(QPHI)), cos(q(QPHI))]
        end if
        call reach_height(pl, q, lm, t)
        q0 = q
        call newton(pl, lm, q, t, conv, it, lim)
        if (present(iterations)) iterations = iterations + it
        if (present(tr)) tr = t
        if (conv) return
        ! the homotopy from the start
        q = q0
        g0 = 0.0_dp
        g0(1:pl%nd) = master_residual(pl, q, lm)
        h = 1.0_dp/HOMOTOPY_STEPS
        do i = 1, HOMOTOPY_STEPS
            k1 = slope(q)
            k2 = slope(moved(q, 0.5_dp*h, k1))
            k3 = slope(moved(q, 0.5_dp*h, k2))
            k4 = slope(moved(q, h, k3))
            q = moved(q, h/6.0_dp, k1 + 2.0_dp*k2 + 2.0_dp*k3 + k4)
            if (.not. all(abs(q) < huge(1.0_dp))) exit
        end do
        t = [sin(q(4)), cos(q(4)), sin(q(5)), cos(q(5)), sin(q(6)), cos(q(6))]
        call newton(pl, lm, q, t, conv, it, NEWTON_MAX)
        if (present(iterations)) iterations = iterations + it + 4*HOMOTOPY_STEPS
        if (present(tr)) tr = t
        if (.not. conv) call set_error(stat, ERR_MODEL, 'platform: no pose of the body '// &
            'satisfies the cables'' lengths here (Newton and the homotopy failed; residual '// &
            sci(maxval(abs(master_residual(pl, q, lm))))//')')
    contains
        !> dq_D/dxi = -A_D^-1 G(q(0)) of the homotopy (0 where the chart is singular)
        pure function slope(qq) result(s)
            real(dp), intent(in) :: qq(6)
            real(dp) :: s(3), tt(6), r(3, 3), ad(3, 3), ainv(3, 3), g(3)
            logical :: regular
            tt = [sin(qq(4)), cos(qq(4)), sin(qq(5)), cos(qq(5)), sin(qq(6)), cos(qq(6))]
            call rot_trig(tt(1), tt(2), tt(3), tt(4), tt(5), tt(6), r)
            call master_rows(pl, qq, r, [-tt(1), tt(2), 0.0_dp], lm, ad, g)
            call small_inverse_fast(pl%nd, ad, ainv, regular)
            s = 0.0_dp
            if (regular) s = -matmul(ainv, g0)
        end function slope
        pure function moved(qq, step, s) result(qm)
            real(dp), intent(in) :: qq(6), step, s(3)
            real(dp) :: qm(6)
            integer :: jj
            qm = qq
            do jj = 1, pl%nd
                qm(pl%dep(jj)) = qq(pl%dep(jj)) + step*s(jj)
            end do
        end function moved
    end subroutine solve_pose

    !> Newton's method on the master cables' constraints for q(dep), t the sines and
    !! cosines of q's angles (updated with them).  Converged when a correction is below
    !! 1e-9 (of the length scale for z): the error left is then of the order of its square.
    pure subroutine newton(pl, lm, q, t, converged, nit, maxit)
        type(platform_t), intent(in) :: pl
        real(dp), intent(in) :: lm(:)
        real(dp), intent(inout) :: q(6), t(6)
        logical, intent(out) :: converged
        integer, intent(out) :: nit
        integer, intent(in) :: maxit            !! most iterations
        real(dp) :: r(3, 3), ad(3, 3), ainv(3, 3), g(3), d(3), lim, dzmax
        logical :: regular
        integer :: k, j
        converged = .false.
        nit = 0
        lim = 1.0e6_dp*max(1.0_dp, pl%lscale)
        do k = 1, maxit
            call rot_trig(t(1), t(2), t(3), t(4), t(5), t(6), r)
            call master_rows(pl, q, r, [-t(1), t(2), 0.0_dp], lm, ad, g, dzmax)
            call small_inverse_fast(pl%nd, ad, ainv, regular)
            if (.not. regular) return
            d = matmul(ainv, g)
            nit = k
            do j = 1, pl%nd
                select case (pl%dep(j))
                case (QZ)
                    q(QZ) = q(QZ) - d(j)
                case (QTHETA)
                    q(QTHETA) = q(QTHETA) - d(j)
                    call turn(t(3), t(4), d(j))
                case (QPHI)
                    q(QPHI) = q(QPHI) - d(j)
                    call turn(t(5), t(6), d(j))
                end select
            end do
            if (.not. (abs(q(QZ)) < lim .and. abs(q(QTHETA)) < lim .and. &
                       abs(q(QPHI)) < lim)) return
            if (abs(d(1)) <= 1.0e-9_dp*pl%lscale .and. abs(d(2)) <= 1.0e-9_dp .and. &
                abs(d(3)) <= 1.0e-9_dp) then
                ! the hanging branch only: every master's body point below its support, the
                ! dependent tilts within the chart (|theta|, |phi| < 90 degrees)
                converged = dzmax < 0.0_dp
                do j = 1, pl%nd
                    if (pl%dep(j) /= QZ) converged = converged .and. &
                                                     abs(q(pl%dep(j))) < 0.5_dp*pi
                end do
                return
            end if
        end do
    end subroutine newton

    !> (s, c) = (sin, cos) of an angle a turned into those of a - d: the addition formulas,
    !! sin d and cos d by their Taylor series when |d| < 0.1 (truncation below 3e-19).
    pure subroutine turn(s, c, d)
        real(dp), intent(inout) :: s, c
        real(dp), intent(in) :: d
        real(dp) :: sd, cd, d2, s0
        if (abs(d) < 0.1_dp) then
            d2 = d*d
            sd = d*(1.0_dp - d2/6.0_dp*(1.0_dp - d2/20.0_dp*(1.0_dp - d2/42.0_dp* &
                                                             (1.0_dp - d2/72.0_dp))))
            cd = 1.0_dp - d2/2.0_dp*(1.0_dp - d2/12.0_dp*(1.0_dp - d2/30.0_dp* &
                                                          (1.0_dp - d2/56.0_dp* &
                                                           (1.0_dp - d2/90.0_dp))))
        else
            sd = sin(d)
            cd = cos(d)
        end if
        s0 = s
        s = s0*cd - c*sd
        c = c*cd + s0*sd
    end subroutine turn

    !> A_D (rows of the master cables) and the residuals g at pose q with rotation r; dzmax
    !! the highest of the masters' body points over its support.
    pure subroutine master_rows(pl, q, r, a2, lm, ad, g, dzmax)
        type(platform_t), intent(in) :: pl
        real(dp), intent(in) :: q(6), r(3, 3), a2(3), lm(:)
        real(dp), intent(out) :: ad(3, 3), g(3)
        real(dp), intent(out), optional :: dzmax
        real(dp) :: rho(3), d(3), p(3)
        integer :: j, i
        ad = 0.0_dp
        g = 0.0_dp
        if (present(dzmax)) dzmax = -huge(1.0_dp)
        do j = 1, pl%nd
            i = pl%master(j)
            p = pl%body(:, i)
            rho = r(:, 1)*p(1) + r(:, 2)*p(2) + r(:, 3)*p(3)
            d = q(1:3) + rho - pl%support(:, i)
            call constraint_row(pl, rho, d, r(:, 1), a2, ad(j, :), g(j))
            g(j) = g(j) - 0.5_dp*lm(j)**2
            if (present(dzmax)) dzmax = max(dzmax, d(3))
        end do
    end subroutine master_rows

    !> The inverse of a (order nd = 2 or 3) by its adjugate; regular = |det a| is at least
    !! CHART_MIN_QUALITY times the product of its rows' norms.
    pure subroutine small_inverse_fast(nd, a, ainv, regular)
        integer, intent(in) :: nd
        real(dp), intent(in) :: a(3, 3)
        real(dp), intent(out) :: ainv(3, 3)
        logical, intent(out) :: regular
        real(dp) :: det, den
        ainv = 0.0_dp
        if (nd == 2) then
            det = a(1, 1)*a(2, 2) - a(1, 2)*a(2, 1)
            den = (a(1, 1)**2 + a(1, 2)**2)*(a(2, 1)**2 + a(2, 2)**2)
            regular = det**2 >= CHART_MIN_QUALITY**2*den .and. det /= 0.0_dp
            if (.not. regular) return
            ainv(1, 1) = a(2, 2)/det
            ainv(1, 2) = -a(1, 2)/det
            ainv(2, 1) = -a(2, 1)/det
            ainv(2, 2) = a(1, 1)/det
        else
            ainv(1, 1) = a(2, 2)*a(3, 3) - a(2, 3)*a(3, 2)
            ainv(1, 2) = a(1, 3)*a(3, 2) - a(1, 2)*a(3, 3)
            ainv(1, 3) = a(1, 2)*a(2, 3) - a(1, 3)*a(2, 2)
            ainv(2, 1) = a(2, 3)*a(3, 1) - a(2, 1)*a(3, 3)
            ainv(2, 2) = a(1, 1)*a(3, 3) - a(1, 3)*a(3, 1)
            ainv(2, 3) = a(1, 3)*a(2, 1) - a(1, 1)*a(2, 3)
            ainv(3, 1) = a(2, 1)*a(3, 2) - a(2, 2)*a(3, 1)
            ainv(3, 2) = a(1, 2)*a(3, 1) - a(1, 1)*a(3, 2)
            ainv(3, 3) = a(1, 1)*a(2, 2) - a(1, 2)*a(2, 1)
            det = a(1, 1)*ainv(1, 1) + a(1, 2)*ainv(2, 1) + a(1, 3)*ainv(3, 1)
            den = sum(a(1, :)**2)*sum(a(2, :)**2)*sum(a(3, :)**2)
            regular = det**2 >= CHART_MIN_QUALITY**2*den .and. det /= 0.0_dp
            if (.not. regular) return
            ainv = ainv/det
        end if
    end subroutine small_inverse_fast

    !> Move q(3) (z) to where the master cables reach on average at q's tilt (t: the sines
    !! and cosines of q's angles).
    pure subroutine reach_height(pl, q, lm, t)
        type(platform_t), intent(in) :: pl
        real(dp), intent(inout) :: q(6)
        real(dp), intent(in) :: lm(:), t(6)
        real(dp) :: r(3, 3), rho(3), h2, zsum, p(3)
        integer :: j, i, cnt
        call rot_trig(t(1), t(2), t(3), t(4), t(5), t(6), r)
        zsum = 0.0_dp
        cnt = 0
        do j = 1, pl%nd
            i = pl%master(j)
            p = pl%body(:, i)
            rho = r(:, 1)*p(1) + r(:, 2)*p(2) + r(:, 3)*p(3)
            h2 = (q(1) + rho(1) - pl%support(1, i))**2 + (q(2) + rho(2) - pl%support(2, i))**2
            if (h2 < lm(j)**2) then
                zsum = zsum + pl%support(3, i) - rho(3) - sqrt(lm(j)**2 - h2)
                cnt = cnt + 1
            end if
        end do
        if (cnt > 0) q(3) = zsum/cnt
    end subroutine reach_height

    !> The pose guessed for the generalized coordinates u (free coordinates, then the
    !! stretches): q(free) = u's, q(dep) from the last pose to first order (g valid), else
    !! the reference pose's.  ok: the guess came from g.
    pure subroutine guess_pose(pl, g, u, q, ok)
        type(platform_t), intent(in) :: pl
        type(pose_guess_t), intent(in) :: g
        real(dp), intent(in) :: u(:)
        real(dp), intent(out) :: q(6)
        logical, intent(out) :: ok
        real(dp) :: du(6)
        integer :: j, c
        ok = g%valid .and. g%nu == size(u)
        if (ok) then
            q = g%q
            do c = 1, g%nu
                du(c) = u(c) - g%u(c)
            end do
            do j = 1, pl%nd
                do c = 1, g%nu
                    q(pl%dep(j)) = q(pl%dep(j)) + g%gam(j, c)*du(c)
                end do
            end do
        else
            q = pl%q_ref
        end if
        do c = 1, pl%nf
            q(pl%free(c)) = u(c)
        end do
    end subroutine guess_pose

    !> Keep a solved pose (its kinematics k, generalized coordinates u) as the next guess.
    pure subroutine keep_guess(g, k, u)
        type(pose_guess_t), intent(inout) :: g
        type(platform_kin_t), intent(in) :: k
        real(dp), intent(in) :: u(:)
        g%valid = .true.
        g%nu = size(u)
        g%q = k%q
        g%u(1:g%nu) = u
        g%gam(:, 1:g%nu) = k%gam(:, 1:g%nu)
    end subroutine keep_guess

    !> Set the reference pose (the guess of solve_pose) and its angles' sines and cosines.
    pure subroutine set_reference(pl, q)
        type(platform_t), intent(inout) :: pl
        real(dp), intent(in) :: q(6)
        pl%q_ref = q
        pl%trig_ref = [sin(q(QTHETA)), cos(q(QTHETA)), sin(q(QPHI)), cos(q(QPHI))]
    end subroutine set_reference

    ! ------------------------------------------------------------------------------------
    ! Kinematics
    ! ------------------------------------------------------------------------------------

    !> The kinematics at pose q (solved: solve_pose) with the free coordinates' rates qfd
    !! and, for elastic cables, the master cables' length rates sd (Qdot = (qfd, sd));
    !! lm the masters' lengths; tr the sines and cosines of q's angles when known
    !! (solve_pose).  Fills k (see platform_kin_t): the partial velocities for the ns = nf
    !! (+ nd with sd) generalized speeds and the accelerations at Qddot = 0.  ERR_MODEL
    !! when the chart is singular at q.
    pure subroutine platform_kinematics(pl, q, qfd, lm, k, stat, sd, tr)
        type(platform_t), intent(in) :: pl
        real(dp), intent(in) :: q(6)            !! the pose
        real(dp), intent(in) :: qfd(:)          !! (nf) rates of the free coordinates
        real(dp), intent(in) :: lm(:)           !! (nd) the master cables' lengths
        type(platform_kin_t), intent(out) :: k
        type(status_t), intent(out) :: stat
        real(dp), intent(in), optional :: sd(:) !! (nd) the master cables' length rates
        real(dp), intent(in), optional :: tr(6) !! sin, cos of psi, theta, phi
        real(dp) :: t(6), ad(3, 3), af(3, 4), m(3), b(3), cd(3), ae(3), w(3), p(3), &
                    qcol(6)
        integer :: i, j, c, nd, nf
        stat%code = 0
        nd = pl%nd
        nf = pl%nf
        k%q = q
        if (present(tr)) then
            t = tr
        else
            t = [sin(q(4)), cos(q(4)), sin(q(5)), cos(q(5)), sin(q(6)), cos(q(6))]
        end if
        call rot_trig(t(1), t(2), t(3), t(4), t(5), t(6), k%rot)
        k%a1 = k%rot(:, 1)
        k%a2 = [-t(1), t(2), 0.0_dp]
        do i = 1, pl%n
            p = pl%body(:, i)
            k%rho(:, i) = k%rot(:, 1)*p(1) + k%rot(:, 2)*p(2) + k%rot(:, 3)*p(3)
            k%d(:, i) = q(1:3) + k%rho(:, i) - pl%support(:, i)
        end do
        p = pl%cg
        k%rhoc = k%rot(:, 1)*p(1) + k%rot(:, 2)*p(2) + k%rot(:, 3)*p(3)
        ! the constraint Jacobian: A_D (dependent) and A_F (free coordinates)
        ad = 0.0_dp
        af = 0.0_dp
        do j = 1, nd
            i = pl%master(j)
            qcol = full_row(k%rho(:, i), k%d(:, i), k%a1, k%a2)
            do c = 1, nd
                ad(j, c) = qcol(pl%dep(c))
            end do
            do c = 1, nf
                af(j, c) = qcol(pl%free(c))
            end do
        end do
        call small_inverse_fast(nd, ad, k%adinv, regular=k%singular)
        k%singular = .not. k%singular
        if (k%singular) then
            call set_error(stat, ERR_MODEL, 'platform: the chart is singular here: a cable '// &
                           'horizontal or the attachments collinear as the cables see them')
            return
        end if
        ! Gamma: q_D' = Gamma Qdot
        k%ns = nf
        if (present(sd)) k%ns = nf + nd
        k%gam = 0.0_dp
        do c = 1, nf
            k%gam(:, c) = -(k%adinv(:, 1)*af(1, c) + k%adinv(:, 2)*af(2, c) + &
                            k%adinv(:, 3)*af(3, c))
        end do
        if (present(sd)) then
            do j = 1, nd
                k%gam(:, nf + j) = k%adinv(:, j)*lm(j)
            end do
        end if
        ! the rates q'
        k%qd = 0.0_dp
        do c = 1, nf
            k%qd(pl%free(c)) = qfd(c)
        end do
        do j = 1, nd
            w(1) = 0.0_dp
            do c = 1, nf
                w(1) = w(1) + k%gam(j, c)*qfd(c)
            end do
            if (present(sd)) then
                do c = 1, nd
                    w(1) = w(1) + k%gam(j, nf + c)*sd(c)
                end do
            end if
            k%qd(pl%dep(j)) = w(1)
        end do
        k%vr = k%qd(1:3)
        k%omega = [k%qd(5)*k%a2(1) + k%qd(6)*k%a1(1), k%qd(5)*k%a2(2) + k%qd(6)*k%a1(2), &
                   k%qd(4) + k%qd(6)*k%a1(3)]
        ! partial velocities: E applied to dq/dQ_c
        do c = 1, k%ns
            qcol = 0.0_dp
            if (c <= nf) qcol(pl%free(c)) = 1.0_dp
            do j = 1, nd
                qcol(pl%dep(j)) = k%gam(j, c)
            end do
            k%vv(:, c) = qcol(1:3)
            k%vw(:, c) = [qcol(5)*k%a2(1) + qcol(6)*k%a1(1), qcol(5)*k%a2(2) + qcol(6)*k%a1(2), &
                          qcol(4) + qcol(6)*k%a1(3)]
        end do
        do i = 1, pl%n
            k%pd(:, i) = k%vr + cross(k%omega, k%rho(:, i))
        end do
        ! alpha at q'' = 0 from the angles' rates: the axes a2, a1 turn
        ae = k%qd(4)*k%qd(5)*[-t(2), -t(1), 0.0_dp] + &
             k%qd(6)*cross([k%qd(5)*k%a2(1), k%qd(5)*k%a2(2), k%qd(4)], k%a1)
        ! the twice-differentiated constraints: A_D q_D'' = -A_F q_F'' + l s'' + b
        b = 0.0_dp
        do j = 1, nd
            i = pl%master(j)
            m = cross(k%rho(:, i), k%d(:, i))
            w = cross(k%omega, cross(k%omega, k%rho(:, i)))
            b(j) = -dot_product(k%pd(:, i), k%pd(:, i)) - dot_product(k%d(:, i), w) &
                   - dot_product(m, ae)
            if (present(sd)) b(j) = b(j) + sd(j)**2
        end do
        cd = k%adinv(:, 1)*b(1) + k%adinv(:, 2)*b(2) + k%adinv(:, 3)*b(3)
        k%a0 = 0.0_dp
        k%al0 = ae
        do j = 1, nd
            select case (pl%dep(j))
            case (QZ)
                k%a0(3) = cd(j)
            case (QTHETA)
                k%al0 = k%al0 + cd(j)*k%a2
            case (QPHI)
                k%al0 = k%al0 + cd(j)*k%a1
            end select
        end do
    end subroutine platform_kinematics

end module platform_geometry
