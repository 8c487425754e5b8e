!> Tests of analysis tensor: the torsion mode of an aligned body against the exact period
!! of pure torsion, the simulated period's small-amplitude limit, the six entries back from
!! the model's own periods (6, 9 and 12 hangs, small amplitude and 20 degrees), how far the
!! projection solution lies, honest uncertainties over 20 noise seeds, the budget against
!! differences of the whole fit, the plan against random directions, hangs given by their
!! attachment points, the amplitude limit, and through the executable: the example deck,
!! a comma-separated table with a header and CR LF, refusals (one line, exit 2, no file),
!! the chi-square warning, a repeatable Monte Carlo.
module test_tensor
    use kinds, only: dp, pi, deg
    use status, only: status_t, STATUS_OK, ERR_DECK, ERR_MODEL
    use testing, only: tester_t, write_text, exists, file_has, count_lines, scratch_dir, &
                       empty_dir, msg_of
    use text, only: itoa, sci
    use deck, only: deck_t, read_deck
    use deck_runs, only: accuracy_of
    use geometry, only: pendulum_t
    use rig, only: rig_t, accuracy_t, make_pendulum
    use floquet, only: torsion_period, check_torsion_scene
    use random, only: rng_t, rng_stream, rng_normal
    use output_io, only: read_kv
    use measurement, only: measurement_t, hang_t, OBS_HANG
    use measurement_read, only: read_hangs
    use hang_model, only: tensor_entries, principal_axes, hang_rig, hang_period, &
        torsion_mode, torsion_mode_t, maxima_drift, turned_hang, rest_pose
    use bifilar_model, only: NSTATE, chart_positions
    use tensor_checks, only: check_moments, TRIANGLE_MARGIN, START_FACTOR
    use tensor_fit, only: tensor_problem_t, tensor_fit_t, tensor_plan_t, problem_of, &
        check_directions, projection, fit_tensor, plan_hangs, design_trace, along_for, &
        DRIFT_MAX, DRIFT_CYCLES
    implicit none
    private

    public :: run_tensor_tests

    character(len=*), parameter :: SCR = 'build/test_tensor'
    character(len=*), parameter :: NL = new_line('a')
    character(len=*), parameter :: CRLF = achar(13)//achar(10)
    !> The test body: mass, principal moments, gravity; its rig.
    real(dp), parameter :: MASS = 3.0_dp, G0 = 9.80665_dp
    real(dp), parameter :: MOMENTS(3) = [0.08_dp, 0.11_dp, 0.14_dp]
    !> The deck lines of the test rig for the executable.
    character(len=*), parameter :: RIG_LINES = &
        '&suspension b = 0.5, b_prime = 0.4, l = 1.2, l_prime = 1.2, g = 9.80665 /'//NL// &
        '&body mass = 3.0, inertia = 0.08, 0.11, 0.14, cg_depth = 0.1, cg_offset = 0 /'//NL

contains

    subroutine run_tensor_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        call scratch_dir(SCR)
        if (t%want('tensor: an aligned hang''s torsion mode is the exact period of torsion')) &
            call test_aligned(t)
        if (t%want('tensor: the rest pose of an asymmetric hang is in equilibrium')) &
            call test_rest(t)
        if (t%want('tensor: the simulated period tends to the torsion mode''s')) &
            call test_small_limit(t)
        if (t%want('tensor: the six entries back from 6, 9 and 12 hangs')) call test_exact(t)
        if (t%want('tensor: the projection solution is off by the coupling')) &
            call test_projection(t)
        if (t%want('tensor: honest u of the principal moments over 20 noise seeds')) &
            call test_coverage(t)
        if (t%want('tensor: the budget against differences of the whole fit')) &
            call test_budget(t)
        if (t%want('tensor: the plan beats random directions')) call test_plan(t)
        if (t%want('tensor: hangs given by their attachment points')) call test_points(t)
        if (t%want('tensor: the amplitude limit')) call test_amplitude(t, exe)
        if (t%want('tensor: the example deck')) call test_example(t, exe)
        if (t%want('tensor: a table with a header, commas and CR LF')) call test_crlf(t, exe)
        if (t%want('tensor: refusals are one line, exit 2 and no file')) &
            call test_refusals(t, exe)
        if (t%want('tensor: chi-square warning')) call test_warning(t, exe)
        if (t%want('tensor: Monte Carlo: threads, kill and resume, MPI ranks')) &
            call test_mc(t, exe)
        if (t%want('tensor: the principal moments a body can have')) call test_moments(t)
        if (t%want('tensor: physical checks through the executable')) &
            call test_physical(t, exe)
    end subroutine run_tensor_tests

    ! ------------------------------------------------------------------ the test body

    !> The test body's tensor: MOMENTS about the axes of the rotation of the quaternion
    !! (0.9, 0.3, -0.2, 0.25) (no axis along a frame axis, products of inertia all nonzero).
    function true_tensor() result(x)
        real(dp) :: x(6)
        real(dp) :: q(4), r(3, 3), jt(3, 3)
        integer :: k
        q = [0.9_dp, 0.3_dp, -0.2_dp, 0.25_dp]
        q = q/norm2(q)
        associate (a => q(1), b => q(2), c => q(3), e => q(4))
            r = reshape([a**2 + b**2 - c**2 - e**2, 2*(b*c + a*e), 2*(b*e - a*c), &
                         2*(b*c - a*e), a**2 - b**2 + c**2 - e**2, 2*(c*e + a*b), &
                         2*(b*e + a*c), 2*(c*e - a*b), a**2 - b**2 - c**2 + e**2], [3, 3])
        end associate
        jt = 0.0_dp
        do k = 1, 3
            jt = jt + MOMENTS(k)*spread(r(:, k), 2, 3)*spread(r(:, k), 1, 3)
        end do
        x = tensor_entries(jt)
    end function true_tensor

    !> A hang of the test rig with up u and along a.
    function rig_hang(u, a, id) result(h)
        real(dp), intent(in) :: u(3), a(3)
        integer, intent(in) :: id
        type(hang_t) :: h
        h%id = id
        h%line = id + 1
        h%up = u/norm2(u)
        h%along = a - dot_product(a, h%up)*h%up
        h%along = h%along/norm2(h%along)
        h%l = 1.2_dp
        h%l_prime = 1.2_dp
        h%b = 0.5_dp
        h%b_prime = 0.4_dp
        h%cg_depth = 0.1_dp
        h%cg_offset = 0.0_dp
    end function rig_hang

    !> A deck of the test rig for problem_of: rtol 1e-12, the given uncertainties.
    function test_deck(u_t, u_dir, u_rig, u_mass) result(d)
        real(dp), intent(in) :: u_t, u_dir, u_rig, u_mass
        type(deck_t) :: d
        d%body%mass = MASS
        d%suspension%g = G0
        d%suspension%b = 0.5_dp
        d%suspension%b_prime = 0.4_dp
        d%suspension%l = 1.2_dp
        d%suspension%l_prime = 1.2_dp
        d%integration%rtol = 1.0e-12_dp
        d%integration%atol = 1.0e-14_dp
        d%tensor%u = [u_mass, u_rig, u_rig, 0.5_dp*u_rig, 0.5_dp*u_rig, 0.0_dp, u_t, 0.0_dp]
        d%tensor%u_direction = u_dir
    end function test_deck

    !> The unit up directions of n = 6, 9 or 12 hangs: faces, edges, corners.
    function directions(n) result(u)
        integer, intent(in) :: n
        real(dp), allocatable :: u(:, :)
        real(dp) :: all(3, 12)
        integer :: k
        all = reshape([1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 0, 1, 0, 1, 0, 1, 1, 1, 1, 1, &
                       1, -1, 1, -1, 1, 1, 1, -1, 0, 1, 0, -1, 0, 1, -1]*1.0_dp, [3, 12])
        u = all(:, 1:n)
        do k = 1, n
            u(:, k) = u(:, k)/norm2(u(:, k))
        end do
    end function directions

    !> A problem of hangs with ups u at amplitude amp whose periods are the model's for the
    !! tensor x on the true rig (`truth`, when given, the hangs as they really were; mass_t,
    !! rig_dl the true mass and a change of every length) plus timing noise noise(i).
    subroutine make_problem(d, u, amp, x, prob, st, truth, mass_t, noise)
        type(deck_t), intent(in) :: d
        real(dp), intent(in) :: u(:, :), amp, x(6)
        type(tensor_problem_t), intent(out) :: prob
        type(status_t), intent(out) :: st
        type(hang_t), intent(in), optional :: truth(:)
        real(dp), intent(in), optional :: mass_t, noise(:)
        type(measurement_t) :: set
        type(hang_t) :: h
        type(rig_t) :: rg
        real(dp) :: m
        integer :: k, n
        n = size(u, 2)
        allocate (set%releases(n), set%obs(n))
        m = MASS
        if (present(mass_t)) m = mass_t
        do k = 1, n
            set%releases(k)%hang = rig_hang(u(:, k), along_for(u(:, k)), k)
            h = set%releases(k)%hang
            if (present(truth)) h = truth(k)
            call hang_rig(m, G0, h, x, rg, st)
            if (st%code == STATUS_OK) call hang_period(rg, acc12(), amp, set%obs(k)%period, st)
            if (st%code /= STATUS_OK) return
            if (present(noise)) set%obs(k)%period = set%obs(k)%period + noise(k)
            set%obs(k)%kind = OBS_HANG
            set%obs(k)%release = k
            set%obs(k)%line = k + 1
            set%obs(k)%amplitude = amp
            set%obs(k)%u_period = d%tensor%u(7)
        end do
        call problem_of(d%tensor, d%suspension, d%body, accuracy_of(d), set, prob)
    end subroutine make_problem

    function acc12() result(acc)
        type(accuracy_t) :: acc
        acc%rtol = 1.0e-12_dp
        acc%atol = 1.0e-14_dp
    end function acc12

    ! ------------------------------------------------------------------ the model

    !> A hang whose vertical is a principal axis, on a rig with equal cables and the mass
    !! centre below the midpoint of CD, twists purely: its torsion mode's period is the
    !! exact period of pure torsion (module floquet's energy integral) at vanishing
    !! amplitude; and its theta_4 maxima do not drift.
    subroutine test_aligned(t)
        type(tester_t), intent(inout) :: t
        type(rig_t) :: rg
        type(pendulum_t) :: p
        type(torsion_mode_t) :: md
        type(status_t) :: st
        real(dp) :: x(6), w(3), v(3, 3), per, dr, ad
        integer :: k, ivert
        x = true_tensor()
        call principal_axes(x, w, v, st)
        do k = 1, 3
            call hang_rig(MASS, G0, rig_hang(v(:, k), along_for(v(:, k)), 1), x, rg, st)
            call t%check('aligned '//itoa(k)//': the rig', st%code == STATUS_OK)
            call make_pendulum(rg, p, st)
            call check_torsion_scene(p, ivert, st)
            call t%check('aligned '//itoa(k)//': a torsion scene: '//msg_of(st), &
                         st%code == STATUS_OK)
            call torsion_period(p, 1.0e-4_dp, ivert, per, st)
            call torsion_mode(rg, md, st)
            call t%check('aligned '//itoa(k)//': torsion mode', st%code == STATUS_OK)
            call t%check_close('aligned '//itoa(k)//': the mode''s period is pure torsion''s', &
                               md%period, per*sqrt(rg%b_prime/rg%g), rtol=1.0e-9_dp)
            call t%check_close('aligned '//itoa(k)//': theta4 all of the mode', md%share, &
                               0.5_dp, rtol=1.0e-9_dp)
            call maxima_drift(rg, acc12(), 3.0_dp, DRIFT_CYCLES, dr, ad, st)
            call t%check('aligned '//itoa(k)//': no drift at 3 deg ('//sci(dr, 2)//')', &
                         st%code == STATUS_OK .and. dr < 1.0e-6_dp)
        end do
    end subroutine test_aligned

    !> The rest pose of a hang with unequal cables, b /= b' and the mass centre off the
    !! midpoint of CD: the body is a three-force member, so the two cables' lines and the
    !! vertical through the mass centre meet in one point (statics, not the equations of
    !! motion); and the pose is not theta = 0.
    subroutine test_rest(t)
        type(tester_t), intent(inout) :: t
        type(hang_t) :: h
        type(rig_t) :: rg
        type(pendulum_t) :: p
        type(status_t) :: st
        real(dp) :: y(NSTATE), c(3), d(3), rs(3), e(3), n(3, 3), bb(3), s, det, py
        h = rig_hang([0.0_dp, 0.0_dp, 1.0_dp], [1.0_dp, 0.0_dp, 0.0_dp], 1)
        h%l_prime = 1.35_dp
        h%cg_offset = 0.06_dp
        call hang_rig(MASS, G0, h, true_tensor(), rg, st)
        call make_pendulum(rg, p, st)
        call rest_pose(p, y, st)
        call t%check('rest: found: '//msg_of(st), st%code == STATUS_OK)
        call chart_positions(p, y, c, d, rs, e, n)
        ! B + s (C - B) = tt D in the plane x = 0 (A at the origin)
        bb = [0.0_dp, -p%big_b, 0.0_dp]
        det = (c(2) - bb(2))*(-d(3)) - (c(3) - bb(3))*(-d(2))
        s = ((-bb(2))*(-d(3)) - (-bb(3))*(-d(2)))/det
        py = bb(2) + s*(c(2) - bb(2))
        call t%check_close('rest: the cables'' lines meet on the vertical through R*', py, &
                           rs(2), atol=1.0e-10_dp)
        call t%check('rest: in the plane of the cables (x = 0), CD tilted', &
                     maxval(abs([c(1), d(1), rs(1)])) < 1.0e-12_dp .and. abs(y(5)) > 1.0e-3_dp)
    end subroutine test_rest

    !> A misaligned hang: the full model's period from a release in the torsion mode's shape
    !! tends to the mode's period as the amplitude vanishes; its maxima drift, the more the
    !! larger the amplitude.
    subroutine test_small_limit(t)
        type(tester_t), intent(inout) :: t
        type(rig_t) :: rg
        type(torsion_mode_t) :: md
        type(status_t) :: st
        real(dp) :: dev(3), tp, dr(2), ad
        real(dp), parameter :: AMPS(3) = [0.04_dp, 0.01_dp, 0.0025_dp]
        integer :: k
        call hang_rig(MASS, G0, rig_hang([0.0_dp, 0.0_dp, 1.0_dp], [1.0_dp, 0.0_dp, 0.0_dp], &
                      1), true_tensor(), rg, st)
        call torsion_mode(rg, md, st)
        call t%check('small limit: the mode tilts the body about CD (theta1/theta4 = '// &
                     sci(md%shape(1), 2)//')', st%code == STATUS_OK .and. &
                     abs(md%shape(1)) > 1.0e-3_dp)
        do k = 1, 3
            call hang_period(rg, acc12(), AMPS(k), tp, st)
            dev(k) = abs(tp/md%period - 1.0_dp)
        end do
        write (*, '(a,3es10.2)') '   |T(A)/T_mode - 1| at 0.04, 0.01, 0.0025 deg:', dev
        call t%check('small limit: within 1e-5 at 0.01 deg', dev(2) < 1.0e-5_dp)
        call t%check('small limit: shrinks with the amplitude', dev(3) < 0.5_dp*dev(2) .and. &
                     dev(2) < 0.5_dp*dev(1))
        call maxima_drift(rg, acc12(), 1.0_dp, DRIFT_CYCLES, dr(1), ad, st)
        call maxima_drift(rg, acc12(), 2.0_dp, DRIFT_CYCLES, dr(2), ad, st)
        write (*, '(a,2es10.2)') '   drift of the maxima at 1 and 2 deg:', dr
        call t%check('small limit: the maxima drift more at 2 deg than at 1', &
                     dr(2) > 1.5_dp*dr(1) .and. dr(1) > 0.0_dp)
    end subroutine test_small_limit

    !> Periods made by the model of the known body give back its six entries to 1e-8 of
    !! the largest principal moment: 6, 9 and 12 hangs, at small amplitude and at 20 deg.
    subroutine test_exact(t)
        type(tester_t), intent(inout) :: t
        type(tensor_problem_t) :: prob
        type(tensor_fit_t) :: fit
        type(status_t) :: st
        real(dp) :: x(6), xp(6), err
        integer :: i, n
        real(dp), parameter :: AMPS(2) = [0.0_dp, 20.0_dp]
        integer :: ia
        x = true_tensor()
        do ia = 1, 2
            do i = 1, 3
                n = 3 + 3*i
                call make_problem(test_deck(0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp), directions(n), &
                                  AMPS(ia), x, prob, st)
                call t%check('exact: periods made', st%code == STATUS_OK)
                call projection(prob, xp, st)
                call fit_tensor(prob, xp, fit, st)
                call t%check('exact '//itoa(n)//' hangs at '//itoa(nint(AMPS(ia)))// &
                             ' deg: fitted: '//msg_of(st), st%code == STATUS_OK)
                err = maxval(abs(fit%x - x))/maxval(MOMENTS)
                write (*, '(a,i0,a,i0,a,es10.2)') '   ', n, ' hangs at ', nint(AMPS(ia)), &
                    ' deg: largest error of an entry / I_max = ', err
                call t%check('exact '//itoa(n)//' hangs at '//itoa(nint(AMPS(ia)))// &
                             ' deg: entries to 1e-8', err < 1.0e-8_dp)
                call t%check_close('exact '//itoa(n)//': principal moment 3', fit%moments(3), &
                                   MOMENTS(3), rtol=1.0e-8_dp)
            end do
        end do
    end subroutine test_exact

    !> The projection solution (the linear formula per hang, then least squares on u . J u)
    !! misses the coupling: for the test body it lies well off the truth, where the exact
    !! fit does not.
    subroutine test_projection(t)
        type(tester_t), intent(inout) :: t
        type(tensor_problem_t) :: prob
        type(tensor_fit_t) :: fit
        type(status_t) :: st
        real(dp) :: x(6), xp(6), e_fit, e_proj
        x = true_tensor()
        call make_problem(test_deck(0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp), directions(9), 0.0_dp, &
                          x, prob, st)
        call projection(prob, xp, st)
        call fit_tensor(prob, xp, fit, st)
        e_fit = maxval(abs(fit%x - x))/maxval(MOMENTS)
        e_proj = maxval(abs(xp - x))/maxval(MOMENTS)
        write (*, '(a,es10.2,a,es10.2)') '   9 hangs, small amplitude: the projection '// &
            'solution is off by', e_proj, ' of I_max, the exact fit by', e_fit
        call t%check('projection: off by more than 1e-4 of I_max', e_proj > 1.0e-4_dp)
        call t%check('projection: a thousand times the exact fit''s error', &
                     e_proj > 1.0e3_dp*e_fit)
        call t%check_close('projection: the reported difference', fit%projection_difference, &
                           maxval(abs(xp - fit%x))/maxval(fit%moments), rtol=1.0e-12_dp)
    end subroutine test_projection

    !> With noise on the periods and on the geometry (how the body was set, the cable
    !! lengths and spacings, the mass), drawn from the stated uncertainties, each principal
    !! moment's 95 % interval covers the truth in at least 17 of 20 seeds.
    subroutine test_coverage(t)
        type(tester_t), intent(inout) :: t
        type(tensor_problem_t) :: prob
        type(tensor_fit_t) :: fit
        type(status_t) :: st
        type(deck_t) :: d
        type(hang_t), allocatable :: truth(:)
        type(rng_t) :: g
        real(dp), allocatable :: u(:, :), noise(:)
        real(dp) :: x(6), xp(6), dl(4), mt, eps(3)
        integer :: seed, k, j, covered(3), n
        real(dp), parameter :: U_T = 2.0e-4_dp, U_DIR = 0.3_dp, U_RIG = 1.0e-3_dp
        real(dp), parameter :: U_MASS = 2.0e-3_dp
        x = true_tensor()
        d = test_deck(U_T, U_DIR, U_RIG, U_MASS)
        u = directions(9)
        n = size(u, 2)
        allocate (truth(n), noise(n))
        covered = 0
        do seed = 1, 20
            g = rng_stream(seed, 0)
            mt = MASS + U_MASS*rng_normal(g)
            do j = 1, 4
                dl(j) = d%tensor%u(1 + j)*rng_normal(g)
            end do
            do k = 1, n
                truth(k) = rig_hang(u(:, k), along_for(u(:, k)), k)
                do j = 1, 3
                    eps(j) = U_DIR*deg*rng_normal(g)
                end do
                truth(k) = turned_hang(truth(k), eps)
                truth(k)%l = truth(k)%l + dl(1)
                truth(k)%l_prime = truth(k)%l_prime + dl(2)
                truth(k)%b = truth(k)%b + dl(3)
                truth(k)%b_prime = truth(k)%b_prime + dl(4)
                noise(k) = U_T*rng_normal(g)
            end do
            call make_problem(d, u, 0.0_dp, x, prob, st, truth, mt, noise)
            call projection(prob, xp, st)
            call fit_tensor(prob, xp, fit, st)
            if (st%code /= STATUS_OK) then
                call t%check('coverage seed '//itoa(seed)//': '//msg_of(st), .false.)
                cycle
            end if
            do k = 1, 3
                if (abs(fit%moments(k) - MOMENTS(k)) <= fit%k95(k)*fit%u_moments(k)) &
                    covered(k) = covered(k) + 1
            end do
        end do
        write (*, '(a,3(i0,1x),a)') '   95 % intervals covering the truth: ', covered, &
            'of 20 (principal moments 1, 2, 3)'
        do k = 1, 3
            call t%check('coverage: moment '//itoa(k)//' covered in '//itoa(covered(k))// &
                         ' of 20 (>= 17)', covered(k) >= 17)
        end do
    end subroutine test_coverage

    !> The budget's line of an input is its change of the fit: b by 1e-4 relative, the
    !! whole fit done again here (central differences), against the budget's contribution
    !! over u_b, entry by entry.
    subroutine test_budget(t)
        type(tester_t), intent(inout) :: t
        type(tensor_problem_t) :: prob, pp
        type(tensor_fit_t) :: fit, fp, fm
        type(status_t) :: st
        type(deck_t) :: d
        real(dp) :: x(6), xp(6), h, dxdb(6)
        integer :: k, kb
        x = true_tensor()
        d = test_deck(1.0e-4_dp, 0.0_dp, 1.0e-3_dp, 0.0_dp)
        call make_problem(d, directions(9), 0.0_dp, x, prob, st)
        call projection(prob, xp, st)
        call fit_tensor(prob, xp, fit, st)
        h = 1.0e-4_dp*0.5_dp
        pp = prob
        do k = 1, size(pp%hangs)
            pp%hangs(k)%b = 0.5_dp + h
        end do
        call fit_tensor(pp, fit%x, fp, st)
        do k = 1, size(pp%hangs)
            pp%hangs(k)%b = 0.5_dp - h
        end do
        call fit_tensor(pp, fit%x, fm, st)
        dxdb = (fp%x - fm%x)/(2.0_dp*h)
        kb = findloc(fit%budget%input, 'b', 1)
        call t%check('budget: a line for b', kb > 0)
        if (kb == 0) return
        do k = 1, 6
            call t%check_close('budget: entry '//itoa(k)//' moves with b as the budget says', &
                               fit%budget(kb)%contribution(k), abs(dxdb(k))*fit%budget(kb)%u, &
                               rtol=1.0e-3_dp, atol=1.0e-4_dp*maxval(abs(dxdb))*fit%budget(kb)%u)
        end do
    end subroutine test_budget

    !> The planner's 9 hangs give a smaller trace of the covariance than 9 random distinct
    !! directions (five sets) on the same body and rig.
    subroutine test_plan(t)
        type(tester_t), intent(inout) :: t
        type(tensor_problem_t) :: prob
        type(tensor_plan_t) :: plan
        type(status_t) :: st
        type(deck_t) :: d
        type(rng_t) :: g
        real(dp) :: x(6), ups(3, 9), als(3, 9), tr, w(3)
        integer :: s, k, j
        x = true_tensor()
        d = test_deck(1.0e-4_dp, 0.2_dp, 1.0e-3_dp, 1.0e-3_dp)
        call make_problem(d, directions(9), 0.0_dp, x, prob, st)
        call plan_hangs(prob, prob%hangs(1), 1.0e-4_dp, x, 9, plan, st)
        call t%check('plan: made: '//msg_of(st), st%code == STATUS_OK .and. plan%n == 9)
        write (*, '(a,es11.3)') '   trace of the planned 9 hangs:', plan%trace
        do s = 1, 5
            g = rng_stream(100 + s, 0)
            do k = 1, 9
                do j = 1, 3
                    w(j) = rng_normal(g)
                end do
                ups(:, k) = w/norm2(w)
                als(:, k) = along_for([0.0_dp, 0.0_dp, 1.0_dp])
                if (abs(ups(3, k)) > 0.9_dp) als(:, k) = [1.0_dp, 0.0_dp, 0.0_dp]
                als(:, k) = als(:, k) - dot_product(als(:, k), ups(:, k))*ups(:, k)
                als(:, k) = als(:, k)/norm2(als(:, k))
            end do
            call design_trace(prob, prob%hangs(1), 1.0e-4_dp, x, ups, als, tr, st)
            write (*, '(a,i0,a,es11.3)') '   trace of random set ', s, ':', tr
            call t%check('plan: smaller trace than random set '//itoa(s), &
                         st%code == STATUS_OK .and. plan%trace < tr)
        end do
    end subroutine test_plan

    !> The same hangs given by their attachment points C, D and &tensor cg read as the
    !! up/along form of the same geometry and give the same fit.
    subroutine test_points(t)
        type(tester_t), intent(inout) :: t
        type(deck_t) :: d1, d2
        type(measurement_t) :: s1, s2
        type(tensor_problem_t) :: p1, p2
        type(tensor_fit_t) :: f1, f2
        type(status_t) :: st
        real(dp) :: u(3, 9), cg(3), c(3), dd(3), a(3), x(6), xp(6)
        type(hang_t) :: h
        type(rig_t) :: rg
        character(len=:), allocatable :: t1, t2
        real(dp) :: per
        integer :: k
        x = true_tensor()
        u = directions(9)
        cg = [0.01_dp, -0.02_dp, 0.03_dp]
        t1 = 'hang up_x up_y up_z along_x along_y along_z period'//NL
        t2 = 'hang c_x c_y c_z d_x d_y d_z period'//NL
        do k = 1, 9
            a = along_for(u(:, k))
            h = rig_hang(u(:, k), a, k)
            call hang_rig(MASS, G0, h, x, rg, st)
            call hang_period(rg, acc12(), 0.0_dp, per, st)
            ! C = cg - (b'/2 + offset) along + depth up, D = C + b' along
            c = cg - 0.2_dp*a + 0.1_dp*u(:, k)
            dd = c + 0.4_dp*a
            t1 = t1//itoa(k)//' '//num3(u(:, k))//' '//num3(a)//' '//num(per)//NL
            t2 = t2//itoa(k)//' '//num3(c)//' '//num3(dd)//' '//num(per)//NL
        end do
        call write_text(SCR//'/pts_up.txt', t1)
        call write_text(SCR//'/pts_cd.txt', t2)
        call write_text(SCR//'/pts_up.nml', "&scene analyses = 'tensor' /"//NL//RIG_LINES// &
            "&integration rtol = 1e-12, atol = 1e-14 /"//NL//"&tensor hangs = 'pts_up.txt' /"//NL)
        call write_text(SCR//'/pts_cd.nml', "&scene analyses = 'tensor' /"//NL// &
            '&suspension b = 0.5, b_prime = 0.4, l = 1.2, l_prime = 1.2, g = 9.80665 /'//NL// &
            '&body mass = 3.0, inertia = 0.08, 0.11, 0.14 /'//NL// &
            "&integration rtol = 1e-12, atol = 1e-14 /"//NL// &
            "&tensor hangs = 'pts_cd.txt', cg = 0.01, -0.02, 0.03 /"//NL)
        call read_deck(SCR//'/pts_up.nml', d1, st)
        call t%check('points: the up/along deck: '//msg_of(st), st%code == STATUS_OK)
        call read_deck(SCR//'/pts_cd.nml', d2, st)
        call t%check('points: the C, D deck without &body cg_depth: '//msg_of(st), &
                     st%code == STATUS_OK)
        call read_hangs(d1%tensor, d1%suspension, d1%body, s1, st)
        call read_hangs(d2%tensor, d2%suspension, d2%body, s2, st)
        call t%check('points: read: '//msg_of(st), st%code == STATUS_OK)
        if (st%code /= STATUS_OK) return
        do k = 1, 9
            associate (h1 => s1%releases(k)%hang, h2 => s2%releases(k)%hang)
                call t%check('points: hang '//itoa(k)//' has the same up, along, b_prime, cg', &
                             maxval(abs(h1%up - h2%up)) < 1.0e-12_dp .and. &
                             maxval(abs(h1%along - h2%along)) < 1.0e-12_dp .and. &
                             abs(h2%b_prime - 0.4_dp) < 1.0e-12_dp .and. &
                             abs(h2%cg_depth - 0.1_dp) < 1.0e-12_dp .and. &
                             abs(h2%cg_offset) < 1.0e-12_dp)
            end associate
        end do
        call problem_of(d1%tensor, d1%suspension, d1%body, accuracy_of(d1), s1, p1)
        call problem_of(d2%tensor, d2%suspension, d2%body, accuracy_of(d2), s2, p2)
        call projection(p1, xp, st)
        call fit_tensor(p1, xp, f1, st)
        call projection(p2, xp, st)
        call fit_tensor(p2, xp, f2, st)
        call t%check('points: the same fit, the truth', st%code == STATUS_OK .and. &
                     maxval(abs(f1%x - f2%x)) < 1.0e-10_dp*maxval(MOMENTS) .and. &
                     maxval(abs(f2%x - x)) < 1.0e-8_dp*maxval(MOMENTS))
    end subroutine test_points

    !> The amplitude limit: a hang whose vertical is a principal axis does not drift, a
    !! misaligned one does; an amplitude beyond the drift the analysis accepts is refused
    !! with one line naming the hang and its limit.
    subroutine test_amplitude(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        type(status_t) :: st
        real(dp) :: x(6), per(9), u(3, 9)
        integer :: k, ex
        character(len=:), allocatable :: tab
        type(rig_t) :: rg
        logical :: l1, l2, l3, l4
        x = true_tensor()
        u = directions(9)
        tab = 'hang,up_x,up_y,up_z,along_x,along_y,along_z,period,amplitude'//NL
        do k = 1, 9
            call hang_rig(MASS, G0, rig_hang(u(:, k), along_for(u(:, k)), k), x, rg, st)
            call hang_period(rg, acc12(), merge(40.0_dp, 2.0_dp, k == 3), per(k), st)
            tab = tab//itoa(k)//','//num3c(u(:, k))//','//num3c(along_for(u(:, k)))//','// &
                num(per(k))//','//trim(merge('40', '2 ', k == 3))//NL
        end do
        call write_text(SCR//'/amp.csv', tab)
        call run_deck_file('amp', "&tensor hangs = 'amp.csv', u_period = 1e-4 /", ex)
        call t%check('amplitude: 40 deg refused, exit 2', ex == 2)
        l1 = count_lines(SCR//'/out_amp.stderr') == 1
        l2 = file_has(SCR//'/out_amp.stderr', 'hang 3 at amplitude = 40')
        l3 = file_has(SCR//'/out_amp.stderr', 'not defined well enough')
        l4 = file_has(SCR//'/out_amp.stderr', 'deg for this hang')
        call t%check('amplitude: one line naming hang 3, the drift and its limit', &
                     l1 .and. l2 .and. l3 .and. l4)
        l1 = empty_dir(SCR//'/out_amp')
        call t%check('amplitude: no file', l1)
    contains
        subroutine run_deck_file(label, group, ex)
            character(len=*), intent(in) :: label, group
            integer, intent(out) :: ex
            call write_text(SCR//'/'//label//'.nml', "&scene analyses = 'tensor' /"//NL// &
                            RIG_LINES//group//NL)
            call execute_command_line('rm -rf '//SCR//'/out_'//label//' && mkdir -p '//SCR// &
                '/out_'//label//' && '//exe//' '//SCR//'/'//label//'.nml --out '//SCR// &
                '/out_'//label//' > '//SCR//'/out_'//label//'.stdout 2> '//SCR//'/out_'// &
                label//'.stderr', exitstat=ex)
        end subroutine run_deck_file
    end subroutine test_amplitude

    ! ------------------------------------------------------------------ the executable

    !> The example deck (its Monte Carlo left out): the true body of its truth deck back to
    !! 1e-8, the projection off, the figure's data, a plan.
    subroutine test_example(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        type(deck_t) :: truth
        type(status_t) :: st
        integer :: ex
        real(dp) :: v, xt(6), jt(3, 3), w(3), vv(3, 3)
        logical :: found
        character(len=512) :: text
        character(len=*), parameter :: O = SCR//'/example'
        logical :: l1, l2
        integer :: k
        call read_deck('input/truth/tensor_example_truth.nml', truth, st)
        call t%check('example: the truth deck', st%code == STATUS_OK)
        jt = 0.0_dp
        do k = 1, 3
            jt = jt + truth%body%inertia(k)*spread(truth%body%btilde(k, :), 2, 3)* &
                 spread(truth%body%btilde(k, :), 1, 3)
        end do
        xt = tensor_entries(jt)
        call principal_axes(xt, w, vv, st)
        call execute_command_line('rm -rf '//O//' && mkdir -p '//O//' && sed -e '// &
            '"s/monte_carlo = 2000/monte_carlo = 0, plan = 9/" input/tensor_example.nml > '// &
            O//'/tensor_example.nml && cp input/tensor_example_hangs.csv '//O//'/ && '//exe// &
            ' '//O//'/tensor_example.nml --out '//O//' > '//O//'.stdout 2> '//O//'.stderr', &
            exitstat=ex)
        l1 = exists(O//'/tensor_example.tensor')
        call t%check('example: runs', ex == 0 .and. l1)
        do k = 1, 6
            call read_kv(O//'/tensor_example.tensor', trim(entry_name(k)), v, found)
            call t%check_close('example: '//entry_name(k)//' is the true body''s', v, xt(k), &
                               atol=1.0e-8_dp*maxval(w))
        end do
        call read_kv(O//'/tensor_example.tensor', 'projection_difference', v, found)
        write (*, '(a,es10.2)') '   example: projection_difference =', v
        call t%check('example: the projection is off by more than 1e-3', v > 1.0e-3_dp)
        l1 = count_lines(O//'/tensor_example.tensor.dat', '#') == 2
        l2 = file_has(O//'/tensor_example.tensor.dat', 'nine hangs')
        call t%check('example: the figure''s data, title on line 1', l1 .and. l2)
        l1 = count_lines(O//'/tensor_example.plan.csv') == 13
        l2 = file_has(O//'.stdout', 'a plan of 9 hangs in')
        call t%check('example: the plan, a table of 9 hangs', l1 .and. l2)
        open (newunit=k, file=O//'.stdout', action='read')
        read (k, '(a)') text
        close (k)
        call t%check('example: the summary line', index(text, 'tensor I_principal = ') > 0)
    end subroutine test_example

    function entry_name(k) result(s)
        integer, intent(in) :: k
        character(len=4) :: s
        character(len=4), parameter :: NAMES(6) = ['J_xx', 'J_yy', 'J_zz', 'J_xy', 'J_xz', &
                                                   'J_yz']
        s = NAMES(k)
    end function entry_name

    !> A table as a spreadsheet writes it: a header with quoted names, commas, CR LF; rows
    !! in another order than the hangs and a hang timed twice.
    subroutine test_crlf(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        type(status_t) :: st
        type(rig_t) :: rg
        real(dp) :: x(6), per, v, u(3, 7)
        character(len=:), allocatable :: tab
        logical :: found, l1
        integer :: k, ex, kk
        x = true_tensor()
        u = directions(7)
        tab = '"hang","up_x","up_y","up_z","along_x","along_y","along_z","cycles",'// &
            '"period"'//CRLF
        do kk = 8, 1, -1
            k = merge(2, kk, kk == 8)
            call hang_rig(MASS, G0, rig_hang(u(:, k), along_for(u(:, k)), k), x, rg, st)
            call hang_period(rg, acc12(), 0.0_dp, per, st)
            tab = tab//itoa(k)//','//num3c(u(:, k))//','//num3c(along_for(u(:, k)))//',20,'// &
                num(20.0_dp*per)//CRLF
        end do
        call write_text(SCR//'/crlf.csv', tab)
        call write_text(SCR//'/crlf.nml', "&scene analyses = 'tensor' /"//CRLF// &
            '&suspension b = 0.5, b_prime = 0.4, l = 1.2, l_prime = 1.2, g = 9.80665 /'// &
            CRLF//'&body mass = 3.0, inertia = 0.08, 0.11, 0.14, cg_depth = 0.1, '// &
            'cg_offset = 0 /'//CRLF//'&integration rtol = 1e-12, atol = 1e-14 /'//CRLF// &
            "&tensor hangs = 'crlf.csv', u_period = 2e-3 /"//CRLF)
        call execute_command_line('rm -rf '//SCR//'/out_crlf && mkdir -p '//SCR// &
            '/out_crlf && '//exe//' '//SCR//'/crlf.nml --out '//SCR//'/out_crlf > '//SCR// &
            '/out_crlf.stdout 2> '//SCR//'/out_crlf.stderr', exitstat=ex)
        call t%check('crlf: runs', ex == 0)
        call read_kv(SCR//'/out_crlf/crlf.tensor', 'J_xy', v, found)
        call t%check_close('crlf: J_xy of the body', v, x(4), atol=1.0e-8_dp*maxval(MOMENTS))
        call read_kv(SCR//'/out_crlf/crlf.tensor', 'rows', v, found)
        l1 = file_has(SCR//'/out_crlf/crlf.tensor', 'hangs = 7')
        call t%check('crlf: 8 rows, 7 hangs', nint(v) == 8 .and. l1)
    end subroutine test_crlf

    !> Refusals through the executable: one line on stderr naming the deck and what is
    !! wrong, exit 2, no file: 5 directions, 6 coplanar directions, up = 0, a missing column,
    !! an unknown column, along parallel to up, C/D points without &tensor cg, a tare or an
    !! added moment (the tensor's fit takes none).
    subroutine test_refusals(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=*), parameter :: HEAD = 'hang up_x up_y up_z along_x along_y along_z '// &
            'period'//NL
        character(len=*), parameter :: ROWS5 = '1 1 0 0 0 1 0 1.5'//NL//'2 0 1 0 0 0 1 1.5'// &
            NL//'3 0 0 1 1 0 0 1.5'//NL//'4 1 1 0 0 0 1 1.5'//NL//'5 1 0 1 0 1 0 1.5'//NL
        call one('five', HEAD//ROWS5//'6 -1 0 -1 0 1 0 1.5'//NL, &
                 '5 distinct directions of up among 6 hangs')
        call one('coplanar', HEAD//'1 1 0 0 0 0 1 1.5'//NL//'2 0 1 0 0 0 1 1.5'//NL// &
                 '3 1 1 0 0 0 1 1.5'//NL//'4 1 -1 0 0 0 1 1.5'//NL//'5 1 2 0 0 0 1 1.5'//NL// &
                 '6 2 1 0 0 0 1 1.5'//NL, 'they do not determine the six entries')
        call one('up0', HEAD//ROWS5//'6 0 0 0 1 0 0 1.5'//NL, 'line 7: up = ')
        call one('nocolumn', 'hang up_x up_y along_x along_y along_z period'//NL// &
                 '1 1 0 0 1 0 1.5'//NL, 'no column ''up_z''')
        call one('unknown', 'hang up_x up_y up_z along_x along_y along_z perod'//NL// &
                 '1 1 0 0 0 1 0 1.5'//NL, 'unknown column ''perod''')
        call one('parallel', HEAD//ROWS5//'6 0 1 1 0 2 2 1.5'//NL, 'is 0 or parallel to up')
        call one('nocg', 'hang c_x c_y c_z d_x d_y d_z period'//NL//'1 0 0 0 1 0 0 1.5'//NL, &
                 'need the mass centre in the body frame')
        ! a tare would be silently left out of the tensor's fit: refused, as is a known
        ! moment added
        call one('tare', HEAD//ROWS5//'6 -1 0 1 0 1 0 1.5'//NL, &
                 'which tensor cannot take', '&measurement tare_I1 = 0.01, u_tare_i1 = 1e-4 /')
        call one('added', HEAD//ROWS5//'6 -1 0 1 0 1 0 1.5'//NL, &
                 'which tensor cannot take', '&measurement added_inertia = 0.02 /')
    contains
        !> The deck of `table` (with the deck line `extra`) refused: exit 2, one line on
        !! stderr naming the deck and holding `word`, no file.
        subroutine one(label, table, word, extra)
            character(len=*), intent(in) :: label, table, word
            character(len=*), intent(in), optional :: extra
            character(len=:), allocatable :: dir, more
            integer :: ex
            logical :: l1, l2, l3
            more = ''
            if (present(extra)) more = extra//NL
            dir = SCR//'/ref_'//label
            call write_text(dir//'.txt', table)
            call write_text(dir//'.nml', "&scene analyses = 'tensor' /"//NL//RIG_LINES// &
                            "&tensor hangs = 'ref_"//label//".txt' /"//NL//more)
            call execute_command_line('rm -rf '//dir//' && mkdir -p '//dir//' && '//exe//' '// &
                dir//'.nml --out '//dir//' > '//dir//'.stdout 2> '//dir//'.stderr', exitstat=ex)
            call t%check('refusal '//label//': exit 2', ex == 2)
            l1 = count_lines(dir//'.stderr') == 1
            l2 = file_has(dir//'.stderr', dir//'.nml')
            l3 = file_has(dir//'.stderr', word)
            call t%check('refusal '//label//': one stderr line naming the deck and '''// &
                         word//'''', l1 .and. l2 .and. l3)
            l1 = empty_dir(dir)
            call t%check('refusal '//label//': no file', l1)
        end subroutine one
    end subroutine test_refusals

    !> A period far off the others: the run succeeds (exit 0) and one warning line on stderr
    !! names the chi-square and the hang with the largest normalised residual.
    subroutine test_warning(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        type(status_t) :: st
        type(rig_t) :: rg
        real(dp) :: x(6), per, u(3, 9)
        character(len=:), allocatable :: tab
        logical :: l1, l2, l3, l4
        integer :: k, ex
        x = true_tensor()
        u = directions(9)
        tab = 'hang up_x up_y up_z along_x along_y along_z period'//NL
        do k = 1, 9
            call hang_rig(MASS, G0, rig_hang(u(:, k), along_for(u(:, k)), k), x, rg, st)
            call hang_period(rg, acc12(), 0.0_dp, per, st)
            if (k == 7) per = per + 3.0e-3_dp
            tab = tab//itoa(k)//' '//num3(u(:, k))//' '//num3(along_for(u(:, k)))//' '// &
                num(per)//NL
        end do
        call write_text(SCR//'/warn.txt', tab)
        call write_text(SCR//'/warn.nml', "&scene analyses = 'tensor' /"//NL//RIG_LINES// &
            "&tensor hangs = 'warn.txt', u_period = 1e-4 /"//NL)
        call execute_command_line('rm -rf '//SCR//'/out_warn && mkdir -p '//SCR// &
            '/out_warn && '//exe//' '//SCR//'/warn.nml --out '//SCR//'/out_warn > '//SCR// &
            '/out_warn.stdout 2> '//SCR//'/out_warn.stderr', exitstat=ex)
        l1 = exists(SCR//'/out_warn/warn.tensor')
        call t%check('warning: exit 0 and the file', ex == 0 .and. l1)
        l1 = count_lines(SCR//'/out_warn.stderr') == 1
        l2 = file_has(SCR//'/out_warn.stderr', 'warning')
        l3 = file_has(SCR//'/out_warn.stderr', 'chi2 = ')
        l4 = file_has(SCR//'/out_warn.stderr', 'hang 7 (line 8)')
        call t%check('warning: one line naming chi2 and hang 7', l1 .and. l2 .and. l3 .and. l4)
    end subroutine test_warning

    !> The Monte Carlo of a small deck gives the same numbers on one thread and on two, and
    !! its u of the principal moments agrees with the first-order u to 25 %; killed after
    !! its first checkpoint and resumed, it gives the uninterrupted file; on two MPI ranks
    !! the serial file.
    subroutine test_mc(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        type(status_t) :: st
        type(rig_t) :: rg
        real(dp) :: x(6), per, u1(3), u2(3), u(3, 9)
        logical :: l1
        character(len=:), allocatable :: tab
        character(len=512) :: line1, line2
        character(len=*), parameter :: HOW(2) = [character(len=30) :: '', &
                                                  '-x BIFILAR_RANK0_COMPUTES=no']
        integer :: k, ex1, ex2, ex
        x = true_tensor()
        u = directions(9)
        tab = 'hang up_x up_y up_z along_x along_y along_z period'//NL
        do k = 1, 9
            call hang_rig(MASS, G0, rig_hang(u(:, k), along_for(u(:, k)), k), x, rg, st)
            call hang_period(rg, acc12(), 0.0_dp, per, st)
            tab = tab//itoa(k)//' '//num3(u(:, k))//' '//num3(along_for(u(:, k)))//' '// &
                num(per)//NL
        end do
        call write_text(SCR//'/mc.txt', tab)
        call write_text(SCR//'/mc.nml', "&scene analyses = 'tensor' /"//NL//RIG_LINES// &
            "&tensor hangs = 'mc.txt', u_period = 2e-4, u_direction = 0.2, u_l = 1e-3, "// &
            'monte_carlo = 400, seed = 5 /'//NL)
        call execute_command_line('rm -rf '//SCR//'/mc1 '//SCR//'/mc2 && mkdir -p '//SCR// &
            '/mc1 '//SCR//'/mc2 && OMP_NUM_THREADS=1 '//exe//' '//SCR//'/mc.nml --out '// &
            SCR//'/mc1 > /dev/null 2>&1', exitstat=ex1)
        call execute_command_line('OMP_NUM_THREADS=2 '//exe//' '//SCR//'/mc.nml --out '// &
            SCR//'/mc2 > /dev/null 2>&1', exitstat=ex2)
        call t%check('mc: both runs succeed', ex1 == 0 .and. ex2 == 0)
        call execute_command_line('bash -c "cmp -s <(grep -v cpu_seconds '//SCR// &
            '/mc1/mc.tensor) <(grep -v cpu_seconds '//SCR//'/mc2/mc.tensor)"', exitstat=ex)
        call t%check('mc: the same file but cpu_seconds on 1 and 2 threads', ex == 0)
        call kv_list(SCR//'/mc1/mc.tensor', 'u_I_principal', line1)
        call kv_list(SCR//'/mc1/mc.tensor', 'u_I_principal_monte_carlo', line2)
        read (line1, *) u1
        read (line2, *) u2
        write (*, '(a,3es10.2,a,3es10.2)') '   u_I_principal first order', u1, ', Monte Carlo', u2
        do k = 1, 3
            call t%check_close('mc: u of moment '//itoa(k)//' as first order', u2(k), u1(k), &
                               rtol=0.25_dp)
        end do
        l1 = exists(SCR//'/mc1/mc.tensor_mc.partial')
        call t%check('mc: its checkpoint removed', .not. l1)
        ! killed after its first checkpoint, resumed: the uninterrupted file
        call write_text(SCR//'/mck.nml', "&scene analyses = 'tensor' /"//NL//RIG_LINES// &
            "&tensor hangs = 'mc.txt', u_period = 2e-4, u_direction = 0.2, u_l = 1e-3, "// &
            'monte_carlo = 1500, seed = 5 /'//NL)
        call execute_command_line('rm -rf '//SCR//'/mck '//SCR//'/mckref && mkdir -p '// &
            SCR//'/mck '//SCR//'/mckref && OMP_NUM_THREADS=1 '//exe//' '//SCR//'/mck.nml '// &
            '--out '//SCR//'/mckref > /dev/null 2>&1', exitstat=ex1)
        call execute_command_line('OMP_NUM_THREADS=1 tests/tools/kill_run.sh '//SCR// &
            '/mck/mck.tensor_mc.partial KILL '//exe//' '//SCR//'/mck.nml --out '//SCR// &
            '/mck --checkpoint 0 > /dev/null 2>&1', exitstat=ex)
        l1 = exists(SCR//'/mck/mck.tensor_mc.partial')
        call t%check('mc: killed after its first checkpoint (exit 137, got '//itoa(ex)//')', &
                     ex1 == 0 .and. ex == 137 .and. l1)
        call execute_command_line(exe//' '//SCR//'/mck.nml --out '//SCR//'/mck --resume > '// &
            SCR//'/mck.stdout 2>&1', exitstat=ex)
        l1 = file_has(SCR//'/mck.stdout', ' resumed from the checkpoint')
        call t%check('mc: resumed from its checkpoint (exit 0)', ex == 0 .and. l1)
        call execute_command_line('bash -c "cmp -s <(grep -v cpu_seconds '//SCR// &
            '/mck/mck.tensor) <(grep -v cpu_seconds '//SCR//'/mckref/mck.tensor)"', exitstat=ex)
        l1 = exists(SCR//'/mck/mck.tensor_mc.partial')
        call t%check('mc: resumed = uninterrupted (cpu_seconds aside), checkpoint removed', &
                     ex == 0 .and. .not. l1)
        ! MPI (when OpenMPI and bin/bifilar_mpi are there): 2 ranks, and 2 ranks of which
        ! rank 0 only hands out work (every sample from the task rank 1 built from the deck
        ! and the payload)
        call execute_command_line('command -v mpirun > /dev/null || exit 1', exitstat=ex)
        l1 = exists(exe//'_mpi')
        if (ex /= 0 .or. .not. l1) then
            write (*, '(a)') 'note: no mpirun or '//exe//'_mpi: the MPI runs of tensor''s '// &
                'Monte Carlo are skipped'
            return
        end if
        do k = 1, 2
            call execute_command_line('rm -rf '//SCR//'/mcmpi && mkdir -p '//SCR//'/mcmpi && '// &
                'env OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 '// &
                'OMP_NUM_THREADS=1 mpirun -q --oversubscribe -np 2 '// &
                trim(HOW(k))//' '//exe//'_mpi '//SCR//'/mc.nml --out '//SCR// &
                '/mcmpi > /dev/null 2>&1', exitstat=ex1)
            call execute_command_line('bash -c "cmp -s <(grep -v cpu_seconds '//SCR// &
                '/mcmpi/mc.tensor) <(grep -v cpu_seconds '//SCR//'/mc1/mc.tensor)"', exitstat=ex)
            call t%check('mc: 2 MPI ranks '//trim(HOW(k))//': the serial file', &
                         ex1 == 0 .and. ex == 0)
        end do
    end subroutine test_mc

    !> check_moments: a tensor not positive definite and one beyond the triangle margin are
    !! refused (ERR_MODEL), one within the margin warned, a lamina (I_max = I_a + I_b)
    !! passes silently; &body size bounds the sum by m d^2/2; a trace START_FACTOR times the
    !! start values' is refused, a smaller factor passes.
    subroutine test_moments(t)
        type(tester_t), intent(inout) :: t
        type(status_t) :: st
        character(len=:), allocatable :: w
        real(dp), parameter :: S0(3) = [0.08_dp, 0.11_dp, 0.14_dp]
        call check_moments([-1.0e-3_dp, 0.1_dp, 0.12_dp], 1.0_dp, 0.0_dp, S0, .false., w, st)
        call t%check('moments: not positive definite refused (exit 4)', st%code == ERR_MODEL &
                     .and. index(st%msg, 'not positive definite') > 0)
        call check_moments([0.05_dp, 0.06_dp, 0.11_dp*TRIANGLE_MARGIN*1.01_dp], 1.0_dp, &
                           0.0_dp, S0, .false., w, st)
        call t%check('moments: beyond the triangle margin refused', st%code == ERR_MODEL &
                     .and. index(st%msg, 'triangle') > 0)
        call check_moments([0.05_dp, 0.06_dp, 0.11_dp*1.05_dp], 1.0_dp, 0.0_dp, S0, .false., &
                           w, st)
        call t%check('moments: within the triangle margin a warning', st%code == STATUS_OK &
                     .and. index(w, 'triangle') > 0)
        call check_moments([0.05_dp, 0.06_dp, 0.11_dp], 1.0_dp, 0.0_dp, S0, .false., w, st)
        call t%check('moments: a lamina passes silently', st%code == STATUS_OK .and. len(w) == 0)
        ! size: a solid ball of diameter d has 3 x m d^2/10 = 0.3 m d^2 < m d^2/2
        call check_moments([0.1_dp, 0.1_dp, 0.1_dp], 1.0_dp, 1.0_dp, S0, .false., w, st)
        call t%check('moments: a ball inside &body size passes', st%code == STATUS_OK)
        call check_moments([0.1_dp, 0.2_dp, 0.25_dp], 1.0_dp, 1.0_dp, S0, .false., w, st)
        call t%check('moments: beyond m size^2/2 refused naming size', st%code == ERR_MODEL &
                     .and. index(st%msg, '&body size') > 0)
        call check_moments(S0*0.9_dp*START_FACTOR, MASS, 0.0_dp, S0, .true., w, st)
        call t%check('moments: within the start factor passes', st%code == STATUS_OK)
        call check_moments(S0*100.0_dp, MASS, 0.0_dp, S0, .true., w, st)
        call t%check('moments: 100 times the start values refused naming cycles', &
                     st%code == ERR_MODEL .and. index(st%msg, 'cycles') > 0)
        call check_moments(S0/100.0_dp, MASS, 0.0_dp, S0, .true., w, st)
        call t%check('moments: 1/100 of the start values refused', st%code == ERR_MODEL)
    end subroutine test_moments

    !> Through the executable: 10-cycle totals typed as periods (no cycles column) are
    !! refused with exit 4 naming the cycles (with &body inertia) and &body size (with it);
    !! a deck with neither is refused (exit 2); a tare in a tensor deck is refused (exit 2);
    !! a tenth hang 0.5 degrees from another gives exit 0 and one warning naming both; a
    !! hang timed twice with u_direction and no u_period fits (exit 0).
    subroutine test_physical(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        type(status_t) :: st
        type(rig_t) :: rg
        real(dp) :: x(6), per(10), u(3, 10), c, s
        character(len=:), allocatable :: tab, tot, twice
        character(len=*), parameter :: HEAD = 'hang up_x up_y up_z along_x along_y along_z '// &
            'period'//NL
        character(len=*), parameter :: RIG_SIZE = &
            '&suspension b = 0.5, b_prime = 0.4, l = 1.2, l_prime = 1.2, g = 9.80665 /'//NL// &
            '&body mass = 3.0, size = 0.5, cg_depth = 0.1, cg_offset = 0 /'//NL
        character(len=*), parameter :: RIG_NONE = &
            '&suspension b = 0.5, b_prime = 0.4, l = 1.2, l_prime = 1.2, g = 9.80665 /'//NL// &
            '&body mass = 3.0, cg_depth = 0.1, cg_offset = 0 /'//NL
        integer :: k, ex
        logical :: l1, l2
        x = true_tensor()
        u(:, 1:9) = directions(9)
        ! the tenth: hang 7's direction turned by 0.5 degrees
        c = cos(0.5_dp*deg)
        s = sin(0.5_dp*deg)
        u(:, 10) = c*u(:, 7) + s*along_for(u(:, 7))
        tab = HEAD
        tot = HEAD
        twice = HEAD
        do k = 1, 10
            call hang_rig(MASS, G0, rig_hang(u(:, k), along_for(u(:, k)), k), x, rg, st)
            call hang_period(rg, acc12(), 0.0_dp, per(k), st)
            tab = tab//itoa(k)//' '//num3(u(:, k))//' '//num3(along_for(u(:, k)))//' '// &
                num(per(k))//NL
            if (k > 9) cycle
            tot = tot//itoa(k)//' '//num3(u(:, k))//' '//num3(along_for(u(:, k)))//' '// &
                num(10.0_dp*per(k))//NL
            twice = twice//itoa(k)//' '//num3(u(:, k))//' '//num3(along_for(u(:, k)))//' '// &
                num(per(k))//NL
            if (k == 2) twice = twice//itoa(k)//' '//num3(u(:, k))//' '// &
                num3(along_for(u(:, k)))//' '//num(per(k))//NL
        end do
        call one('totals', tot, RIG_LINES, '', 4, 'cycles')
        call one('totals_size', tot, RIG_SIZE, '', 4, '&body size')
        call one('no_start', tab, RIG_NONE, '', 2, '&body inertia')
        call one('tare', tab, RIG_LINES, '&measurement tare_i1 = 0.01 /'//NL, 2, 'tare_i1')
        ! near-parallel: exit 0, one warning line naming hangs 7 and 10
        call write_text(SCR//'/phys_near.txt', tab)
        call write_text(SCR//'/phys_near.nml', "&scene analyses = 'tensor' /"//NL// &
            RIG_LINES//"&tensor hangs = 'phys_near.txt', u_period = 1e-4 /"//NL)
        call execute_command_line('rm -rf '//SCR//'/phys_near && mkdir -p '//SCR// &
            '/phys_near && '//exe//' '//SCR//'/phys_near.nml --out '//SCR//'/phys_near > '// &
            SCR//'/phys_near.stdout 2> '//SCR//'/phys_near.stderr', exitstat=ex)
        l1 = count_lines(SCR//'/phys_near.stderr') == 1
        l2 = file_has(SCR//'/phys_near.stderr', 'hangs 7 (line 8) and 10 (line 11), 0.50 deg')
        call t%check('physical: hangs 0.5 deg apart: exit 0, one warning naming both', &
                     ex == 0 .and. l1 .and. l2)
        ! a hang timed twice, u_direction given, u_period 0: the fit runs
        call write_text(SCR//'/phys_twice.txt', twice)
        call write_text(SCR//'/phys_twice.nml', "&scene analyses = 'tensor' /"//NL// &
            RIG_LINES//"&tensor hangs = 'phys_twice.txt', u_direction = 0.2 /"//NL)
        call execute_command_line('rm -rf '//SCR//'/phys_twice && mkdir -p '//SCR// &
            '/phys_twice && '//exe//' '//SCR//'/phys_twice.nml --out '//SCR//'/phys_twice > '// &
            SCR//'/phys_twice.stdout 2> '//SCR//'/phys_twice.stderr', exitstat=ex)
        l1 = exists(SCR//'/phys_twice/phys_twice.tensor')
        call t%check('physical: a hang timed twice with u_direction and no u_period fits '// &
                     '(exit '//itoa(ex)//')', ex == 0 .and. l1)
    contains
        subroutine one(label, table, rigl, extra, code, word)
            character(len=*), intent(in) :: label, table, rigl, extra, word
            integer, intent(in) :: code
            character(len=:), allocatable :: dir
            integer :: e
            logical :: a1, a2, a3
            dir = SCR//'/phys_'//label
            call write_text(dir//'.txt', table)
            call write_text(dir//'.nml', "&scene analyses = 'tensor' /"//NL//rigl//extra// &
                            "&tensor hangs = 'phys_"//label//".txt', u_period = 1e-3 /"//NL)
            call execute_command_line('rm -rf '//dir//' && mkdir -p '//dir//' && '//exe// &
                ' '//dir//'.nml --out '//dir//' > '//dir//'.stdout 2> '//dir//'.stderr', &
                exitstat=e)
            a1 = count_lines(dir//'.stderr') == 1
            a2 = file_has(dir//'.stderr', word)
            a3 = empty_dir(dir)
            call t%check('physical '//label//': exit '//itoa(code)//' (got '//itoa(e)// &
                         '), one line naming '''//word//''', no file', &
                         e == code .and. a1 .and. a2 .and. a3)
        end subroutine one
    end subroutine test_physical

    !> The value text of `key = a, b, c`.
    subroutine kv_list(path, key, val)
        character(len=*), intent(in) :: path, key
        character(len=*), intent(out) :: val
        integer :: u, ios
        character(len=1024) :: line
        val = ''
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        do while (ios == 0)
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (index(line, key//' = ') == 1) then
                val = line(len(key) + 4:)
                exit
            end if
        end do
        close (u)
    end subroutine kv_list

    function num(x) result(s)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: s
        character(len=32) :: buf
        write (buf, '(es24.16)') x
        s = trim(adjustl(buf))
    end function num

    function num3(v) result(s)
        real(dp), intent(in) :: v(3)
        character(len=:), allocatable :: s
        s = num(v(1))//' '//num(v(2))//' '//num(v(3))
    end function num3

    function num3c(v) result(s)
        real(dp), intent(in) :: v(3)
        character(len=:), allocatable :: s
        s = num(v(1))//','//num(v(2))//','//num(v(3))
    end function num3c

end module test_tensor
