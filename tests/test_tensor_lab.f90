!> Tests of analysis tensor as a laboratory uses it: a fixture that hangs with the body
!! (&tensor fixture_*) in each hang's model, the mass centre fitted with the tensor from
!! the periods and the hangs' attitudes (estimate = 'tensor cg'), and the planner (faces,
!! edges and corners; hangs added to a table; the deck's cycles and timings).  The truths
!! are made here: the periods of body and fixture come from the paper's model of the
!! whole that hangs, composed in this file from the attachment points (not by the code
!! under test).
module test_tensor_lab
    use kinds, only: dp, pi, deg
    use status, only: status_t, STATUS_OK
    use testing, only: tester_t, write_text, exists, file_has, count_lines, scratch_dir, &
                       empty_dir, msg_of
    use text, only: itoa, sci
    use deck, only: deck_t, read_deck
    use deck_runs, only: accuracy_of
    use rig, only: rig_t, accuracy_t
    use random, only: rng_t, rng_stream, rng_normal
    use vectors, only: cross
    use measurement, only: measurement_t, hang_t, OBS_HANG
    use hang_model, only: tensor_entries, tensor_matrix, hang_rig, hang_period, principal_axes
    use tensor_fit, only: tensor_problem_t, tensor_fit_t, tensor_plan_t, problem_of, &
        projection, fit_tensor, along_for, plan_hangs, design_trace
    implicit none
    private

    public :: run_tensor_lab_tests

    character(len=*), parameter :: SCR = 'build/test_tensor_lab'
    character(len=*), parameter :: NL = new_line('a')
    real(dp), parameter :: G0 = 9.80665_dp

    !> A rig and body of a test: mass, tensor, the rig of every hang.
    type :: body_t
        real(dp) :: mass = 3.0_dp
        real(dp) :: x(6) = 0.0_dp
        real(dp) :: b = 0.5_dp, b_prime = 0.4_dp, l = 1.2_dp, depth = 0.1_dp
    end type body_t

contains

    subroutine run_tensor_lab_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        call scratch_dir(SCR)
        if (t%want('tensor_lab: a fixture in the hangs'' model gives the body''s tensor')) &
            call test_fixture(t)
        if (t%want('tensor_lab: a fixture through the executable; a tare refused')) &
            call test_fixture_exe(t, exe)
        if (t%want('tensor_lab: the CubeSat''s mass centre across the strings')) &
            call test_cubesat_cg(t)
        if (t%want('tensor_lab: the mass centre from six hangs'' attitudes')) &
            call test_six_attitudes(t)
        if (t%want('tensor_lab: the mass centre through the executable')) &
            call test_cg_exe(t, exe)
        if (t%want('tensor_lab: the CubeSat''s mass centre by Monte Carlo')) &
            call test_cubesat_cg_mc(t, exe)
        if (t%want('tensor_lab: the plan takes faces, edges and corners')) call test_plan_dirs(t)
        if (t%want('tensor_lab: the plan''s u with the deck''s cycles and timings')) &
            call test_plan_u(t, exe)
        if (t%want('tensor_lab: hangs added to a table')) call test_plan_add(t, exe)
        if (t%want('tensor_lab: the plan for the tensor and the mass centre')) &
            call test_plan_cg(t)
        if (t%want('tensor_lab: the new keys refused out of range')) call test_keys(t, exe)
    end subroutine run_tensor_lab_tests

    ! ------------------------------------------------------------------ made truths

    !> The test body of suite tensor: principal moments 0.08, 0.11, 0.14 about generic axes.
    function test_tensor() result(x)
        real(dp) :: x(6)
        real(dp) :: q(4), r(3, 3), jt(3, 3)
        real(dp), parameter :: MOMENTS(3) = [0.08_dp, 0.11_dp, 0.14_dp]
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
    end function test_tensor

    !> The CubeSat of tests/bench/cubesat_truth.nml: 4 kg, principal moments 0.0418,
    !! 0.0425, 0.0072 about axes turned about 4 degrees from its frame.
    function cubesat_tensor() result(x)
        real(dp) :: x(6)
        real(dp) :: bt(3, 3), jt(3, 3)
        real(dp), parameter :: MOMENTS(3) = [0.0418_dp, 0.0425_dp, 0.0072_dp]
        integer :: k
        bt(1, :) = [0.997727658824_dp, -0.029584845692_dp, -0.060533096089_dp]
        bt(2, :) = [0.030675569456_dp, 0.999381923200_dp, 0.017169188074_dp]
        bt(3, :) = [0.059987734206_dp, -0.018987061014_dp, 0.998018518495_dp]
        jt = 0.0_dp
        do k = 1, 3
            jt = jt + MOMENTS(k)*spread(bt(k, :), 2, 3)*spread(bt(k, :), 1, 3)
        end do
        x = tensor_entries(jt)
    end function cubesat_tensor

    !> The nine face, edge and corner directions of up and their alongs (the CubeSat's
    !! table).
    subroutine nine_hangs(ups, alongs)
        real(dp), intent(out) :: ups(3, 9), alongs(3, 9)
        integer :: k
        ups = reshape([1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 0, 1, 0, 1, 0, 1, 1, 1, 1, 1, 1, -1, 1, &
                       -1, 1, 1]*1.0_dp, [3, 9])
        alongs = reshape([0, 1, 0, 1, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, -1, 0, 1, 1, &
                          0, 1, 1, 0]*1.0_dp, [3, 9])
        do k = 1, 9
            ups(:, k) = ups(:, k)/norm2(ups(:, k))
            alongs(:, k) = alongs(:, k)/norm2(alongs(:, k))
        end do
    end subroutine nine_hangs

    !> The true hang of a body whose table says (up, along; the mass centre cg_depth below
    !! the midpoint of CD) when the whole that hangs has its mass centre at gc from where the
    !! table puts it (body frame): C and D fixed in the body, the hang's up the normal to CD
    !! in the plane of C, D and gc.
    function true_hang(bd, up, along, gc) result(h)
        type(body_t), intent(in) :: bd
        real(dp), intent(in) :: up(3), along(3), gc(3)
        type(hang_t) :: h
        real(dp) :: c(3), p(3), s
        c = bd%depth*up - 0.5_dp*bd%b_prime*along
        s = dot_product(gc - c, along)
        p = (gc - c) - s*along
        h%up = -p/norm2(p)
        h%along = along
        h%cg_depth = norm2(p)
        h%cg_offset = s - 0.5_dp*bd%b_prime
        h%b = bd%b
        h%b_prime = bd%b_prime
        h%l = bd%l
        h%l_prime = bd%l
    end function true_hang

    !> The inertia of a unit mass at r about the origin: |r|^2 1 - r r^T.
    pure function shift(r) result(m)
        real(dp), intent(in) :: r(3)
        real(dp) :: m(3, 3)
        integer :: k
        m = -spread(r, 2, 3)*spread(r, 1, 3)
        do k = 1, 3
            m(k, k) = m(k, k) + dot_product(r, r)
        end do
    end function shift

    !> The small-amplitude period of a body (its mass centre dcg from the table's) with a
    !! fixture (mass mf at rf from the table's mass centre, inertia jf) hung as the table
    !! says (up, along), and the gravity direction in the body frame at rest.
    subroutine made_period(bd, dcg, mf, rf, jf, up, along, per, gdir, st)
        type(body_t), intent(in) :: bd
        real(dp), intent(in) :: dcg(3), mf, rf(3), jf(3, 3), up(3), along(3)
        real(dp), intent(out) :: per, gdir(3)
        type(status_t), intent(out) :: st
        real(dp) :: gc(3), jc(3, 3)
        type(hang_t) :: h
        type(rig_t) :: rg
        gc = (bd%mass*dcg + mf*rf)/(bd%mass + mf)
        jc = tensor_matrix(bd%x) + bd%mass*shift(dcg - gc) + jf + mf*shift(rf - gc)
        h = true_hang(bd, up, along, gc)
        ! gravity lies in the plane of C, D and the mass centre; at rest CD leans by the
        ! body's tilt, which only turns gravity about the plane's normal
        gdir = -cos(0.3_dp*deg)*h%up + sin(0.3_dp*deg)*h%along
        call hang_rig(bd%mass + mf, G0, h, tensor_entries(jc), rg, st)
        if (st%code == STATUS_OK) call hang_period(rg, acc12(), 0.0_dp, per, st)
    end subroutine made_period

    function acc12() result(acc)
        type(accuracy_t) :: acc
        acc%rtol = 1.0e-12_dp
        acc%atol = 1.0e-14_dp
    end function acc12

    !> A deck of the body's rig for problem_of, with the uncertainties given.
    function lab_deck(bd, u_t, u_dir) result(d)
        type(body_t), intent(in) :: bd
        real(dp), intent(in) :: u_t, u_dir
        type(deck_t) :: d
        d%body%mass = bd%mass
        d%suspension%g = G0
        d%suspension%b = bd%b
        d%suspension%b_prime = bd%b_prime
        d%suspension%l = bd%l
        d%suspension%l_prime = bd%l
        d%integration%rtol = 1.0e-12_dp
        d%integration%atol = 1.0e-14_dp
        d%tensor%u = [1.0e-3_dp, 1.0e-3_dp, 1.0e-3_dp, 5.0e-4_dp, 5.0e-4_dp, 0.0_dp, u_t, 0.0_dp]
        d%tensor%u_direction = u_dir
    end function lab_deck

    !> A problem of the deck's uncertainties with the hangs (up, along as the table says),
    !! periods per, attitudes gdir (when given).
    subroutine lab_problem(d, bd, ups, alongs, per, prob, gdir)
        type(deck_t), intent(in) :: d
        type(body_t), intent(in) :: bd
        real(dp), intent(in) :: ups(:, :), alongs(:, :), per(:)
        type(tensor_problem_t), intent(out) :: prob
        real(dp), intent(in), optional :: gdir(:, :)
        type(measurement_t) :: set
        integer :: k, n
        n = size(per)
        allocate (set%releases(n), set%obs(n))
        do k = 1, n
            associate (h => set%releases(k)%hang)
                h%id = k
                h%line = k + 1
                h%up = ups(:, k)
                h%along = alongs(:, k)
                h%l = bd%l
                h%l_prime = bd%l
                h%b = bd%b
                h%b_prime = bd%b_prime
                h%cg_depth = bd%depth
                h%cg_offset = 0.0_dp
                if (present(gdir)) then
                    h%attitude = .true.
                    h%gravity = gdir(:, k)/norm2(gdir(:, k))
                end if
            end associate
            set%obs(k)%kind = OBS_HANG
            set%obs(k)%release = k
            set%obs(k)%line = k + 1
            set%obs(k)%period = per(k)
            set%obs(k)%u_period = d%tensor%u(7)
        end do
        call problem_of(d%tensor, d%suspension, d%body, accuracy_of(d), set, prob)
    end subroutine lab_problem

    !> The fit from the projection solution.
    subroutine fit_of(prob, fit, st)
        type(tensor_problem_t), intent(in) :: prob
        type(tensor_fit_t), intent(out) :: fit
        type(status_t), intent(out) :: st
        real(dp) :: xp(6)
        call projection(prob, xp, st)
        if (st%code == STATUS_OK) call fit_tensor(prob, xp, fit, st)
    end subroutine fit_of

    ! ------------------------------------------------------------------ fixtures

    !> A body and a fixture (turning with the body) hung in nine directions: fitted with the
    !! fixture given, the body's tensor comes back to 1e-6 on exact periods and within U
    !! when the fixture's stated values are half a u off; fitted without it, the principal
    !! moments are off by the fixture's share.  The budget names the fixture's inputs.
    subroutine test_fixture(t)
        type(tester_t), intent(inout) :: t
        type(body_t) :: bd
        type(deck_t) :: d
        type(tensor_problem_t) :: prob
        type(tensor_fit_t) :: fit, fit0
        type(status_t) :: st
        real(dp) :: ups(3, 9), als(3, 9), per(9), gd(3, 9), mf, rf(3), jf(3, 3), err, w(3)
        real(dp) :: v(3, 3), share, wt(3), vt(3, 3)
        real(dp), parameter :: UM = 0.01_dp, UC = 0.002_dp, UJ = 1.0e-4_dp
        integer :: k
        logical :: names
        bd%x = test_tensor()
        call nine_hangs(ups, als)
        mf = 0.3_dp
        rf = [0.04_dp, -0.03_dp, 0.05_dp]
        jf = reshape([2.0e-3_dp, 2.0e-4_dp, 0.0_dp, 2.0e-4_dp, 3.0e-3_dp, -1.0e-4_dp, &
                      0.0_dp, -1.0e-4_dp, 1.5e-3_dp], [3, 3])
        do k = 1, 9
            call made_period(bd, [0.0_dp, 0.0_dp, 0.0_dp], mf, rf, jf, ups(:, k), als(:, k), &
                             per(k), gd(:, k), st)
            if (st%code /= STATUS_OK) exit
        end do
        call t%check('fixture: periods made: '//msg_of(st), st%code == STATUS_OK)
        if (st%code /= STATUS_OK) return
        call principal_axes(bd%x, wt, vt, st)
        ! exact periods, the fixture given
        d = lab_deck(bd, 1.0e-4_dp, 0.0_dp)
        d%tensor%fixture_mass = mf
        d%tensor%fixture_cg = rf
        d%tensor%fixture_inertia = jf
        call lab_problem(d, bd, ups, als, per, prob)
        call fit_of(prob, fit, st)
        err = maxval(abs(fit%x - bd%x))/maxval(wt)
        write (*, '(a,es10.2)') '   with the fixture: largest error of an entry / I_max = ', err
        call t%check('fixture: fitted: '//msg_of(st), st%code == STATUS_OK)
        call t%check('fixture: the body''s tensor to 1e-6 on exact periods', err < 1.0e-6_dp)
        ! without it: off by the fixture's share
        d = lab_deck(bd, 1.0e-4_dp, 0.0_dp)
        call lab_problem(d, bd, ups, als, per, prob)
        call fit_of(prob, fit0, st)
        call principal_axes(fit0%x, w, v, st)
        share = maxval(abs(w - wt)/wt)
        write (*, '(a,3f8.4)') '   without it: principal moments off by (relative) ', &
            (w - wt)/wt
        call t%check('fixture: without it the moments are off by 5 to 12 %', &
                     share > 0.05_dp .and. share < 0.12_dp)
        ! the fixture as stated half a u off the truth: the body within U
        d = lab_deck(bd, 1.0e-4_dp, 0.0_dp)
        d%tensor%fixture_mass = mf + 0.5_dp*UM
        d%tensor%fixture_cg = rf + 0.5_dp*UC
        d%tensor%fixture_inertia = jf - 0.5_dp*UJ
        d%tensor%u_fixture_mass = UM
        d%tensor%u_fixture_cg = UC
        d%tensor%u_fixture_inertia = UJ
        call lab_problem(d, bd, ups, als, per, prob)
        call fit_of(prob, fit, st)
        call t%check('fixture: u given: fitted: '//msg_of(st), st%code == STATUS_OK)
        if (st%code /= STATUS_OK) return
        write (*, '(a,6f7.2)') '   fixture half a u off: error / u of each entry ', &
            (fit%x - bd%x)/fit%u_x
        call t%check('fixture: half a u off: every entry within U = 2 u', &
                     all(abs(fit%x - bd%x) <= 2.0_dp*fit%u_x))
        names = any(fit%budget%input == 'fixture_mass') .and. &
                any(fit%budget%input == 'fixture_cg') .and. &
                any(fit%budget%input == 'fixture_inertia')
        call t%check('fixture: the budget has fixture_mass, fixture_cg, fixture_inertia', names)
    end subroutine test_fixture

    !> Through the executable: a deck with a fixture in the hang's frame fits (exit 0, the
    !! budget line of the fixture), and &measurement tare_i1 in a tensor deck is refused
    !! with one line naming &tensor fixture_*.
    subroutine test_fixture_exe(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        type(body_t) :: bd
        type(status_t) :: st
        real(dp) :: ups(3, 9), als(3, 9), per, gd(3), mf, rf(3), jf(3, 3), rb(3), jb(3, 3)
        real(dp) :: r(3, 3), c(3), xf(9)
        character(len=:), allocatable :: tab, rigl, fixl, dir
        integer :: k, ex
        logical :: l1, l2, l3
        bd%x = test_tensor()
        call nine_hangs(ups, als)
        ! a fixture that stays with the hang: 0.3 kg 0.02 m across and 0.03 m below CD's
        ! midpoint, its inertia along the hang's axes
        mf = 0.3_dp
        rf = [0.0_dp, 0.02_dp, -0.03_dp]
        jf = 0.0_dp
        jf(1, 1) = 4.0e-4_dp
        jf(2, 2) = 1.0e-4_dp
        jf(3, 3) = 4.0e-4_dp
        tab = 'hang up_x up_y up_z along_x along_y along_z period'//NL
        do k = 1, 9
            r(:, 1) = als(:, k)
            r(:, 2) = cross(ups(:, k), als(:, k))
            r(:, 3) = ups(:, k)
            c = bd%depth*ups(:, k)              ! the midpoint of CD from the mass centre
            rb = c + matmul(r, rf)
            jb = matmul(r, matmul(jf, transpose(r)))
            call made_period(bd, [0.0_dp, 0.0_dp, 0.0_dp], mf, rb, jb, ups(:, k), als(:, k), &
                             per, gd, st)
            tab = tab//itoa(k)//' '//num3(ups(:, k))//' '//num3(als(:, k))//' '//num(per)//NL
        end do
        call t%check('fixture exe: periods made: '//msg_of(st), st%code == STATUS_OK)
        rigl = '&suspension b = 0.5, b_prime = 0.4, l = 1.2, l_prime = 1.2, g = 9.80665 /'// &
            NL//'&body mass = 3.0, inertia = 0.08, 0.11, 0.14, cg_depth = 0.1, cg_offset = 0 /'// &
            NL//'&integration rtol = 1e-12, atol = 1e-14 /'//NL
        xf = reshape(jf, [9])
        fixl = ", fixture_mass = 0.3, fixture_cg = 0, 0.02, -0.03, fixture_inertia = "// &
            num(xf(1))//', 0, 0, 0, '//num(xf(5))//', 0, 0, 0, '//num(xf(9))// &
            ", u_fixture_mass = 0.002, u_fixture_cg = 0.001, fixture_frame = 'hang'"
        dir = SCR//'/fix_hang'
        call write_text(dir//'.txt', tab)
        call write_text(dir//'.nml', "&scene analyses = 'tensor' /"//NL//rigl// &
            "&tensor hangs = 'fix_hang.txt', u_period = 1e-4"//fixl//" /"//NL)
        call execute_command_line('rm -rf '//dir//' && mkdir -p '//dir//' && '//exe//' '// &
            dir//'.nml --out '//dir//' > '//dir//'.stdout 2> '//dir//'.stderr', exitstat=ex)
        l1 = file_has(dir//'/fix_hang.tensor', 'fixture_mass')
        l2 = file_has(dir//'/fix_hang.tensor', 'fixture_cg')
        call t%check('fixture exe: a fixture in the hang''s frame: exit 0 (got '//itoa(ex)// &
                     '), its budget lines', ex == 0 .and. l1 .and. l2)
        call t%check('fixture exe: the body''s principal moments to 1e-8', &
                     maxval(abs(kv3(dir//'/fix_hang.tensor', 'I_principal') - &
                                [0.08_dp, 0.11_dp, 0.14_dp])) < 1.0e-9_dp)
        ! a tare in a tensor deck
        dir = SCR//'/fix_tare'
        call write_text(dir//'.txt', tab)
        call write_text(dir//'.nml', "&scene analyses = 'tensor' /"//NL//rigl// &
            '&measurement tare_i1 = 0.01 /'//NL//"&tensor hangs = 'fix_tare.txt' /"//NL)
        call execute_command_line('rm -rf '//dir//' && mkdir -p '//dir//' && '//exe//' '// &
            dir//'.nml --out '//dir//' > '//dir//'.stdout 2> '//dir//'.stderr', exitstat=ex)
        l1 = count_lines(dir//'.stderr') == 1
        l2 = file_has(dir//'.stderr', '&tensor fixture_*')
        l3 = empty_dir(dir)
        call t%check('fixture exe: tare_i1 refused: exit 2, one line naming &tensor '// &
                     'fixture_*, no file', ex == 2 .and. l1 .and. l2 .and. l3)
    end subroutine test_fixture_exe

    ! ------------------------------------------------------------------ the mass centre

    !> The CubeSat hung in its nine directions with its mass centre 3.5 mm from where the
    !! table puts it (across the strings by 1 to 3 mm in most hangs).  Fitted as the table
    !! says (the mass centre in the plane of the strings) its products of inertia are off
    !! by far more than their U; fitted with estimate = 'tensor cg' and the hangs'
    !! attitudes they are within U, and so is the mass centre; on exact data both to 1e-6.
    subroutine test_cubesat_cg(t)
        type(tester_t), intent(inout) :: t
        type(body_t) :: bd
        type(deck_t) :: d
        type(tensor_problem_t) :: prob
        type(tensor_fit_t) :: fit
        type(status_t) :: st
        type(rng_t) :: g
        real(dp) :: ups(3, 9), als(3, 9), per(9), pn(9), gd(3, 9), gn(3, 9), jz(3, 3), off
        real(dp), parameter :: DCG(3) = [2.0e-3_dp, -2.5e-3_dp, 1.5e-3_dp]
        real(dp), parameter :: UT = 2.0e-4_dp, UA = 0.05_dp, UD = 0.05_dp
        integer :: k, j
        bd%mass = 4.0_dp
        bd%x = cubesat_tensor()
        bd%b = 0.12_dp
        bd%b_prime = 0.12_dp
        bd%l = 0.8_dp
        bd%depth = 0.17_dp
        jz = 0.0_dp
        call nine_hangs(ups, als)
        g = rng_stream(31, 0)
        do k = 1, 9
            call made_period(bd, DCG, 0.0_dp, [0.0_dp, 0.0_dp, 0.0_dp], jz, ups(:, k), &
                             als(:, k), per(k), gd(:, k), st)
            if (st%code /= STATUS_OK) exit
            write (*, '(a,i0,a,f6.2,a)') '   hang ', k, ': rolled ', &
                asin(dot_product(gd(:, k), cross(ups(:, k), als(:, k))))/deg, ' deg'
            pn(k) = per(k) + UT*rng_normal(g)
            do j = 1, 3
                gn(j, k) = gd(j, k) + UA*deg*rng_normal(g)
            end do
        end do
        call t%check('cubesat cg: periods made: '//msg_of(st), st%code == STATUS_OK)
        if (st%code /= STATUS_OK) return
        ! as the table says: the products of inertia off by more than U
        d = lab_deck(bd, UT, UD)
        call lab_problem(d, bd, ups, als, pn, prob)
        call fit_of(prob, fit, st)
        off = maxval(abs(fit%x(4:6) - bd%x(4:6)))
        write (*, '(a,es10.2,a,3f8.2)') '   as in the plane: products off by ', &
            off/0.0425_dp, ' of I_max, error / u ', (fit%x(4:6) - bd%x(4:6))/fit%u_x(4:6)
        call t%check('cubesat cg: in the plane of the strings the products are off beyond U', &
                     st%code == STATUS_OK .and. any(abs(fit%x(4:6) - bd%x(4:6)) > &
                                                    2.0_dp*fit%u_x(4:6)))
        ! estimate = 'tensor cg', exact data
        d = lab_deck(bd, UT, UD)
        d%tensor%estimate = 'tensor cg'
        d%tensor%u_attitude = UA
        call lab_problem(d, bd, ups, als, per, prob, gd)
        call fit_of(prob, fit, st)
        call t%check('cubesat cg: exact data fitted: '//msg_of(st), st%code == STATUS_OK)
        if (st%code /= STATUS_OK) return
        write (*, '(a,es10.2,a,es10.2,a)') '   exact data: entries to ', &
            maxval(abs(fit%x - bd%x))/0.0425_dp, ' of I_max, mass centre to ', &
            maxval(abs(fit%dcg - DCG)), ' m'
        call t%check('cubesat cg: exact data: entries to 1e-6 of I_max, the mass centre to '// &
                     '1e-6 m', maxval(abs(fit%x - bd%x)) < 1.0e-6_dp*0.0425_dp .and. &
                     maxval(abs(fit%dcg - DCG)) < 1.0e-6_dp)
        ! noisy data
        call lab_problem(d, bd, ups, als, pn, prob, gn)
        call fit_of(prob, fit, st)
        call t%check('cubesat cg: noisy data fitted: '//msg_of(st), st%code == STATUS_OK)
        if (st%code /= STATUS_OK) return
        write (*, '(a,3f7.2,a,3f7.2)') '   tensor cg: products error / u ', &
            (fit%x(4:6) - bd%x(4:6))/fit%u_x(4:6), ', mass centre error / u ', &
            (fit%dcg - DCG)/fit%u_dcg
        write (*, '(a,3es10.2,a)') '   u of the mass centre ', fit%u_dcg, ' m'
        call t%check('cubesat cg: the products within U = 2 u', &
                     all(abs(fit%x(4:6) - bd%x(4:6)) <= 2.0_dp*fit%u_x(4:6)))
        call t%check('cubesat cg: the mass centre within U = 2 u', &
                     all(abs(fit%dcg - DCG) <= 2.0_dp*fit%u_dcg))
        call t%check('cubesat cg: the joint covariance is 9 x 9 and symmetric', &
                     size(fit%cov_all, 1) == 9 .and. &
                     maxval(abs(fit%cov_all - transpose(fit%cov_all))) <= &
                     1.0e-12_dp*maxval(abs(fit%cov_all)))
    end subroutine test_cubesat_cg

    !> Six hangs with their attitudes: the mass centre (4 mm off) within U of the truth.
    subroutine test_six_attitudes(t)
        type(tester_t), intent(inout) :: t
        type(body_t) :: bd
        type(deck_t) :: d
        type(tensor_problem_t) :: prob
        type(tensor_fit_t) :: fit
        type(status_t) :: st
        type(rng_t) :: g
        real(dp) :: ups(3, 9), als(3, 9), per(6), gd(3, 6), jz(3, 3)
        real(dp), parameter :: DCG(3) = [-3.0e-3_dp, 1.0e-3_dp, 2.5e-3_dp]
        real(dp), parameter :: UT = 1.0e-4_dp, UA = 0.1_dp
        integer :: k, j
        bd%x = test_tensor()
        jz = 0.0_dp
        call nine_hangs(ups, als)
        g = rng_stream(47, 0)
        do k = 1, 6
            call made_period(bd, DCG, 0.0_dp, [0.0_dp, 0.0_dp, 0.0_dp], jz, ups(:, k), &
                             als(:, k), per(k), gd(:, k), st)
            if (st%code /= STATUS_OK) exit
            per(k) = per(k) + UT*rng_normal(g)
            do j = 1, 3
                gd(j, k) = gd(j, k) + UA*deg*rng_normal(g)
            end do
        end do
        call t%check('six attitudes: periods made: '//msg_of(st), st%code == STATUS_OK)
        if (st%code /= STATUS_OK) return
        d = lab_deck(bd, UT, 0.02_dp)
        d%tensor%estimate = 'tensor cg'
        d%tensor%u_attitude = UA
        call lab_problem(d, bd, ups(:, 1:6), als(:, 1:6), per, prob, gd)
        call fit_of(prob, fit, st)
        call t%check('six attitudes: fitted: '//msg_of(st), st%code == STATUS_OK)
        if (st%code /= STATUS_OK) return
        write (*, '(a,3es10.2,a,3f7.2)') '   mass centre ', fit%dcg, ', error / u ', &
            (fit%dcg - DCG)/fit%u_dcg
        call t%check('six attitudes: the mass centre within U = 2 u of the truth', &
                     all(abs(fit%dcg - DCG) <= 2.0_dp*fit%u_dcg) .and. all(fit%u_dcg > 0.0_dp))
    end subroutine test_six_attitudes

    !> Through the executable: a table with gx, gy, gz (and one with tilt) and estimate =
    !! 'tensor cg' writes cg, u_cg and the joint correlation, and with a Monte Carlo its
    !! mean and u of cg too; attitude columns without it are refused with one line.
    subroutine test_cg_exe(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        type(body_t) :: bd
        type(status_t) :: st
        real(dp) :: ups(3, 9), als(3, 9), per, gd(3), jz(3, 3), tl
        real(dp), parameter :: DCG(3) = [1.0e-3_dp, -2.0e-3_dp, 1.5e-3_dp]
        character(len=:), allocatable :: tab, tabt, rigl, dir
        integer :: k, ex
        bd%x = test_tensor()
        jz = 0.0_dp
        call nine_hangs(ups, als)
        tab = 'hang up_x up_y up_z along_x along_y along_z period gx gy gz'//NL
        tabt = 'hang up_x up_y up_z along_x along_y along_z period tilt'//NL
        do k = 1, 9
            call made_period(bd, DCG, 0.0_dp, [0.0_dp, 0.0_dp, 0.0_dp], jz, ups(:, k), &
                             als(:, k), per, gd, st)
            tab = tab//itoa(k)//' '//num3(ups(:, k))//' '//num3(als(:, k))//' '//num(per)// &
                ' '//num3(gd)//NL
            ! the roll about CD: gravity = -cos(tilt) up + sin(tilt) (up x along), the
            ! along part (CD's lean) aside
            tl = atan2(dot_product(gd, cross(ups(:, k), als(:, k))), -dot_product(gd, ups(:, k)))
            tabt = tabt//itoa(k)//' '//num3(ups(:, k))//' '//num3(als(:, k))//' '//num(per)// &
                ' '//num(tl/deg)//NL
        end do
        rigl = '&suspension b = 0.5, b_prime = 0.4, l = 1.2, l_prime = 1.2, g = 9.80665 /'// &
            NL//'&body mass = 3.0, inertia = 0.08, 0.11, 0.14, cg_depth = 0.1, cg_offset = 0 /'// &
            NL//'&integration rtol = 1e-12, atol = 1e-14 /'//NL
        call one('cg_g', tab, ", estimate = 'tensor cg', u_attitude = 0.05", 0, 'cg')
        call one('cg_tilt', tabt, ", estimate = 'tensor cg', u_attitude = 0.05", 0, 'cg')
        call one('cg_noest', tab, '', 2, 'estimate = ''tensor cg''')
        call one('cg_mc', tab, ", estimate = 'tensor cg', u_attitude = 0.05, monte_carlo = 10", &
                 0, 'cg')
    contains
        subroutine one(label, table, extra, code, word)
            character(len=*), intent(in) :: label, table, extra, word
            integer, intent(in) :: code
            logical :: ok, l1, l2, l3
            real(dp) :: c(3)
            dir = SCR//'/'//label
            call write_text(dir//'.txt', table)
            call write_text(dir//'.nml', "&scene analyses = 'tensor' /"//NL//rigl// &
                "&tensor hangs = '"//label//".txt', u_period = 1e-5, u_direction = 0.02"// &
                extra//" /"//NL)
            call execute_command_line('rm -rf '//dir//' && mkdir -p '//dir//' && '//exe//' '// &
                dir//'.nml --out '//dir//' > '//dir//'.stdout 2> '//dir//'.stderr', &
                exitstat=ex)
            if (code /= 0) then
                l1 = count_lines(dir//'.stderr') == 1
                l2 = file_has(dir//'.stderr', word)
                l3 = empty_dir(dir)
                call t%check('cg exe '//label//': exit '//itoa(code)//' (got '//itoa(ex)// &
                             '), one line naming '//word//', no file', ex == code .and. l1 .and. &
                             l2 .and. l3)
                return
            end if
            l1 = file_has(dir//'/'//label//'.tensor', 'u_cg = ')
            l2 = file_has(dir//'/'//label//'.tensor', 'correlation_tensor_cg(9,:) = ')
            ok = ex == 0 .and. l1 .and. l2
            if (index(extra, 'monte_carlo') > 0) then
                c = kv3(dir//'/'//label//'.tensor', 'u_cg_monte_carlo')
                ok = ok .and. all(abs(c) < 1.0_dp)
                c = kv3(dir//'/'//label//'.tensor', 'cg_monte_carlo_mean')
                ok = ok .and. all(abs(c) < 1.0_dp)
                l1 = file_has(dir//'/'//label//'.tensor', 'NaN')
                ok = ok .and. .not. l1
            end if
            c = kv3(dir//'/'//label//'.tensor', 'cg')
            write (*, '(a,3es12.4)') '   '//label//': cg = ', c
            call t%check('cg exe '//label//': exit 0 (got '//itoa(ex)//'), cg, u_cg and the '// &
                         'joint correlation written, cg to 1e-6 m', ok .and. &
                         maxval(abs(c - DCG)) < 1.0e-6_dp)
        end subroutine one
    end subroutine test_cg_exe

    !> The noisy CubeSat of test_cubesat_cg through the executable with a Monte Carlo of
    !! 400 samples: it exits 0 and writes no NaN, the Monte Carlo u of each coordinate of
    !! the mass centre agrees with the first-order u within 20 %, and the true mass centre
    !! lies within cg +- 1.96 u of the Monte Carlo.
    subroutine test_cubesat_cg_mc(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        type(body_t) :: bd
        type(status_t) :: st
        type(rng_t) :: g
        real(dp) :: ups(3, 9), als(3, 9), per, gd(3), gn(3), jz(3, 3), c(3), u1(3), umc(3)
        real(dp), parameter :: DCG(3) = [2.0e-3_dp, -2.5e-3_dp, 1.5e-3_dp]
        real(dp), parameter :: UT = 2.0e-4_dp, UA = 0.05_dp
        character(len=:), allocatable :: tab, dir, out
        integer :: k, j, ex
        logical :: ok
        bd%mass = 4.0_dp
        bd%x = cubesat_tensor()
        bd%b = 0.12_dp
        bd%b_prime = 0.12_dp
        bd%l = 0.8_dp
        bd%depth = 0.17_dp
        jz = 0.0_dp
        call nine_hangs(ups, als)
        g = rng_stream(31, 0)
        tab = 'hang up_x up_y up_z along_x along_y along_z period gx gy gz'//NL
        do k = 1, 9
            call made_period(bd, DCG, 0.0_dp, [0.0_dp, 0.0_dp, 0.0_dp], jz, ups(:, k), &
                             als(:, k), per, gd, st)
            if (st%code /= STATUS_OK) exit
            per = per + UT*rng_normal(g)
            do j = 1, 3
                gn(j) = gd(j) + UA*deg*rng_normal(g)
            end do
            tab = tab//itoa(k)//' '//num3(ups(:, k))//' '//num3(als(:, k))//' '//num(per)// &
                ' '//num3(gn/norm2(gn))//NL
        end do
        call t%check('cubesat cg mc: periods made: '//msg_of(st), st%code == STATUS_OK)
        if (st%code /= STATUS_OK) return
        dir = SCR//'/cubesat_mc'
        call write_text(dir//'.txt', tab)
        call write_text(dir//'.nml', "&scene analyses = 'tensor' /"//NL// &
            '&suspension b = 0.12, b_prime = 0.12, l = 0.8, l_prime = 0.8, g = 9.80665 /'//NL// &
            '&body mass = 4.0, inertia = 0.0418, 0.0425, 0.0072, cg_depth = 0.17, '// &
            'cg_offset = 0 /'//NL//'&integration rtol = 1e-12, atol = 1e-14 /'//NL// &
            "&tensor hangs = 'cubesat_mc.txt', u_mass = 1e-3, u_l = 1e-3, u_l_prime = 1e-3, "// &
            'u_b = 5e-4, u_b_prime = 5e-4, u_period = 2e-4, u_direction = 0.05, '// &
            "estimate = 'tensor cg', u_attitude = 0.05, monte_carlo = 400, seed = 7 /"//NL)
        call execute_command_line('rm -rf '//dir//' && mkdir -p '//dir//' && '//exe//' '// &
            dir//'.nml --out '//dir//' > '//dir//'.stdout 2> '//dir//'.stderr', exitstat=ex)
        out = dir//'/cubesat_mc.tensor'
        c = kv3(out, 'cg')
        u1 = kv3(out, 'u_cg')
        umc = kv3(out, 'u_cg_monte_carlo')
        ok = ex == 0 .and. all(abs(c) < 1.0_dp) .and. all(u1 > 0.0_dp .and. u1 < 1.0_dp) .and. &
            all(umc > 0.0_dp .and. umc < 1.0_dp)
        if (ok) ok = .not. file_has(out, 'NaN')
        call t%check('cubesat cg mc: exit 0 (got '//itoa(ex)//'), cg, u_cg and '// &
                     'u_cg_monte_carlo written, no NaN', ok)
        if (.not. ok) return
        write (*, '(a,3f7.3,a,3f7.2)') '   Monte Carlo u / first-order u of cg ', umc/u1, &
            ', error / u_mc ', (c - DCG)/umc
        call t%check('cubesat cg mc: the Monte Carlo u of cg within 20 % of the first-order u', &
                     all(abs(umc/u1 - 1.0_dp) <= 0.2_dp))
        call t%check('cubesat cg mc: the true mass centre within cg +- 1.96 u_cg_monte_carlo', &
                     all(abs(c - DCG) <= 1.96_dp*umc))
    end subroutine test_cubesat_cg_mc

    ! ------------------------------------------------------------------ the plan

    !> plan = 12 takes 12 of the 13 face, edge and corner directions, none twice (u and -u
    !! one), corners among them; plan = 15 takes all 13, then two again.
    subroutine test_plan_dirs(t)
        type(tester_t), intent(inout) :: t
        type(body_t) :: bd
        type(deck_t) :: d
        type(tensor_problem_t) :: prob
        type(tensor_plan_t) :: plan
        type(status_t) :: st
        type(hang_t) :: h0
        integer :: n, i, j, nc, twice, dist
        bd%x = test_tensor()
        d = lab_deck(bd, 1.0e-3_dp, 0.2_dp)
        call lab_problem(d, bd, reshape([0.0_dp, 0.0_dp, 1.0_dp], [3, 1]), &
                         reshape([1.0_dp, 0.0_dp, 0.0_dp], [3, 1]), [1.0_dp], prob)
        h0 = prob%hangs(1)
        do n = 12, 15, 3
            call plan_hangs(prob, h0, 1.0e-3_dp, bd%x, n, plan, st)
            call t%check('plan dirs: plan = '//itoa(n)//' made: '//msg_of(st), &
                         st%code == STATUS_OK .and. plan%n == n)
            if (st%code /= STATUS_OK) return
            nc = 0
            twice = 0
            do i = 1, n
                if (count(abs(plan%up(:, i)) > 0.1_dp) == 3) nc = nc + 1
                do j = 1, i - 1
                    if (abs(dot_product(plan%up(:, i), plan%up(:, j))) > 1.0_dp - 1.0e-9_dp) &
                        twice = twice + 1
                end do
            end do
            dist = n - twice
            write (*, '(a,i0,a,i0,a,i0,a)') '   plan = ', n, ': ', dist, ' distinct directions, ', &
                nc, ' corners'
            call t%check('plan dirs: plan = '//itoa(n)//': '//itoa(min(n, 13))//' distinct '// &
                         'directions, corners among them', dist == min(n, 13) .and. nc >= 3)
        end do
    end subroutine test_plan_dirs

    !> The plan's predicted u of hangs timed 3 times over 10 cycles each (u_period 2 ms of
    !! each total, no other u) is the fit's u of those hangs (to 2 %, first order, small
    !! amplitude), and one timing of one cycle (what the plan assumed without the table's
    !! timings) is 10 times off or more; through the executable (with the rig's u), plan = 9 on such a table writes a u of
    !! the same size as the fit's and a table of 3 rows of 10 cycles per hang.
    subroutine test_plan_u(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        type(body_t) :: bd
        type(deck_t) :: d
        type(tensor_problem_t) :: prob
        type(tensor_fit_t) :: fit
        type(status_t) :: st
        type(measurement_t) :: set
        type(hang_t) :: h0
        real(dp) :: ups(3, 9), als(3, 9), per(9), gd(3), jz(3, 3), tr, ux(6), ux1(6), uf(6), up(6)
        character(len=:), allocatable :: tab, dir
        real(dp), parameter :: UT = 2.0e-3_dp
        integer :: k, r, ex, i
        logical :: l1, l2, l3
        bd%x = test_tensor()
        jz = 0.0_dp
        call nine_hangs(ups, als)
        ! the timing alone (the rig's u and the directions' would hide the factor)
        d = lab_deck(bd, UT, 0.0_dp)
        d%tensor%u(1:6) = 0.0_dp
        allocate (set%releases(9), set%obs(27))
        tab = 'hang up_x up_y up_z along_x along_y along_z period cycles'//NL
        do k = 1, 9
            call made_period(bd, [0.0_dp, 0.0_dp, 0.0_dp], 0.0_dp, [0.0_dp, 0.0_dp, 0.0_dp], &
                             jz, ups(:, k), als(:, k), per(k), gd, st)
            set%releases(k)%hang = prob_hang(k)
            do r = 1, 3
                i = 3*(k - 1) + r
                set%obs(i)%kind = OBS_HANG
                set%obs(i)%release = k
                set%obs(i)%line = i + 1
                set%obs(i)%cycles = 10.0_dp
                set%obs(i)%period = per(k)
                set%obs(i)%u_period = UT/10.0_dp
                tab = tab//itoa(k)//' '//num3(ups(:, k))//' '//num3(als(:, k))//' '// &
                    num(10.0_dp*per(k))//' 10'//NL
            end do
        end do
        call problem_of(d%tensor, d%suspension, d%body, accuracy_of(d), set, prob)
        call fit_of(prob, fit, st)
        call t%check('plan u: fitted: '//msg_of(st), st%code == STATUS_OK)
        if (st%code /= STATUS_OK) return
        h0 = prob%hangs(1)
        call design_trace(prob, h0, UT/10.0_dp/sqrt(3.0_dp), bd%x, ups, als, tr, st, u_x=ux)
        call design_trace(prob, h0, UT, bd%x, ups, als, tr, st, u_x=ux1)
        write (*, '(a,6es10.2)') '   fit''s u         ', fit%u_x
        write (*, '(a,6es10.2)') '   predicted u     ', ux
        write (*, '(a,6es10.2)') '   one cycle, once ', ux1
        call t%check('plan u: the prediction with 10 cycles, 3 timings is the fit''s u to 2 %', &
                     maxval(abs(ux/fit%u_x - 1.0_dp)) < 0.02_dp)
        call t%check('plan u: one cycle, once is 10 times off or more', &
                     minval(ux1/fit%u_x) > 10.0_dp)
        ! through the executable
        dir = SCR//'/plan_u'
        call write_text(dir//'.txt', tab)
        call write_text(dir//'.nml', "&scene analyses = 'tensor' /"//NL// &
            '&suspension b = 0.5, b_prime = 0.4, l = 1.2, l_prime = 1.2, g = 9.80665 /'//NL// &
            '&body mass = 3.0, inertia = 0.08, 0.11, 0.14, cg_depth = 0.1, cg_offset = 0 /'//NL// &
            "&tensor hangs = 'plan_u.txt', u_mass = 1e-3, u_l = 1e-3, u_l_prime = 1e-3, "// &
            "u_b = 5e-4, u_b_prime = 5e-4, u_period = 2e-3, u_direction = 0.05, plan = 9 /"//NL)
        call execute_command_line('rm -rf '//dir//' && mkdir -p '//dir//' && '//exe//' '// &
            dir//'.nml --out '//dir//' > '//dir//'.stdout 2> '//dir//'.stderr', exitstat=ex)
        up = kv6(dir//'/plan_u.tensor', 'plan_u')
        uf = [kv1(dir//'/plan_u.tensor', 'u_J_xx'), kv1(dir//'/plan_u.tensor', 'u_J_yy'), &
              kv1(dir//'/plan_u.tensor', 'u_J_zz'), kv1(dir//'/plan_u.tensor', 'u_J_xy'), &
              kv1(dir//'/plan_u.tensor', 'u_J_xz'), kv1(dir//'/plan_u.tensor', 'u_J_yz')]
        write (*, '(a,6es10.2)') '   exe: plan_u / fit''s u ', up/uf
        l1 = file_has(dir//'/plan_u.plan.csv', 'each timed 3 times over 10 cycles')
        l2 = file_has(dir//'/plan_u.plan.csv', ',10,0')
        l3 = count_lines(dir//'/plan_u.plan.csv') == 4 + 27
        call t%check('plan u: exe: exit 0, plan_u within a factor 2 of the fit''s u, rows of '// &
                     '10 cycles', ex == 0 .and. all(up/uf > 0.5_dp .and. up/uf < 2.0_dp) .and. &
                     l1 .and. l2 .and. l3)
    contains
        function prob_hang(k) result(h)
            integer, intent(in) :: k
            type(hang_t) :: h
            h%id = k
            h%line = 3*k - 1
            h%up = ups(:, k)
            h%along = als(:, k)
            h%l = bd%l
            h%l_prime = bd%l
            h%b = bd%b
            h%b_prime = bd%b_prime
            h%cg_depth = bd%depth
            h%cg_offset = 0.0_dp
        end function prob_hang
    end subroutine test_plan_u

    !> The plan with the mass centre fitted (estimate = 'tensor cg'), 8 hangs for the
    !! CubeSat (its mass centre 2 to 3 mm from the table's): on a table made from the
    !! planned hangs (periods with 0.2 ms noise, attitudes with 0.05 deg, the only inputs
    !! with a u), the fit's u of the mass centre and of the entries are the plan's
    !! predicted ones to 10 % (the plan is linearised where the table puts the mass
    !! centre, the fit 3 mm away, at noisy data).  The plan
    !! for the six entries alone is fitted the same way: the criterion the cg plan
    !! minimises (the entries' variances plus (m b')^2 the mass centre's), from the fits'
    !! own covariances, is lower for the cg plan when the two plans differ, and equal when
    !! they are the same.
    subroutine test_plan_cg(t)
        type(tester_t), intent(inout) :: t
        type(body_t) :: bd
        type(deck_t) :: d
        type(tensor_problem_t) :: prob
        type(tensor_plan_t) :: pc, pt
        type(tensor_fit_t) :: fc, ft
        type(status_t) :: st
        type(hang_t) :: h0
        real(dp) :: crit_c, crit_t, wcg
        real(dp), parameter :: DCG(3) = [2.0e-3_dp, -2.5e-3_dp, 1.5e-3_dp]
        real(dp), parameter :: UT = 2.0e-4_dp, UA = 0.05_dp
        integer, parameter :: N = 8
        logical :: same
        integer :: i, j
        bd%mass = 4.0_dp
        bd%x = cubesat_tensor()
        bd%b = 0.12_dp
        bd%b_prime = 0.12_dp
        bd%l = 0.8_dp
        bd%depth = 0.17_dp
        d = lab_deck(bd, UT, 0.0_dp)
        d%tensor%u(1:6) = 0.0_dp
        d%tensor%estimate = 'tensor cg'
        d%tensor%u_attitude = UA
        call lab_problem(d, bd, reshape([0.0_dp, 0.0_dp, 1.0_dp], [3, 1]), &
                         reshape([1.0_dp, 0.0_dp, 0.0_dp], [3, 1]), [1.0_dp], prob)
        h0 = prob%hangs(1)
        wcg = (bd%mass*bd%b_prime)**2
        call plan_hangs(prob, h0, UT, bd%x, N, pc, st)
        call t%check('plan cg: planned: '//msg_of(st), st%code == STATUS_OK .and. pc%n == N)
        if (st%code /= STATUS_OK) return
        d%tensor%estimate = 'tensor'
        call lab_problem(d, bd, reshape([0.0_dp, 0.0_dp, 1.0_dp], [3, 1]), &
                         reshape([1.0_dp, 0.0_dp, 0.0_dp], [3, 1]), [1.0_dp], prob)
        call plan_hangs(prob, h0, UT, bd%x, N, pt, st)
        call t%check('plan cg: the tensor''s plan: '//msg_of(st), st%code == STATUS_OK)
        if (st%code /= STATUS_OK) return
        d%tensor%estimate = 'tensor cg'
        call fit_plan(pc, 11, fc)
        if (st%code /= STATUS_OK) return
        write (*, '(a,3es10.2)') '   predicted u(cg) ', pc%u_cg
        write (*, '(a,3es10.2)') '   fit''s u(cg)     ', fc%u_dcg
        write (*, '(a,6f7.3)') '   u(J) fit / plan ', fc%u_x/pc%u_x
        call t%check('plan cg: the predicted u of the mass centre is the fit''s to 10 %', &
                     all(pc%u_cg > 0.0_dp) .and. maxval(abs(fc%u_dcg/pc%u_cg - 1.0_dp)) < 0.10_dp)
        call t%check('plan cg: the predicted u of the entries are the fit''s to 10 %', &
                     maxval(abs(fc%u_x/pc%u_x - 1.0_dp)) < 0.10_dp)
        call t%check('plan cg: the fit of the planned hangs has the truth within 3 u', &
                     all(abs(fc%dcg - DCG) <= 3.0_dp*fc%u_dcg) .and. &
                     all(abs(fc%x - bd%x) <= 3.0_dp*fc%u_x))
        ! the tensor's plan, fitted with the mass centre
        call fit_plan(pt, 11, ft)
        if (st%code /= STATUS_OK) return
        same = .true.
        do i = 1, N
            same = same .and. any([(abs(dot_product(pc%up(:, i), pt%up(:, j))) > &
                                    1.0_dp - 1.0e-9_dp, j=1, N)])
        end do
        crit_c = sum(fc%u_x**2) + wcg*sum(fc%u_dcg**2)
        crit_t = sum(ft%u_x**2) + wcg*sum(ft%u_dcg**2)
        write (*, '(a,l1,a,2es11.3,a,3es10.2)') '   same directions: ', same, &
            ', criterion cg plan, tensor plan ', crit_c, crit_t, '; tensor plan u(cg) ', &
            ft%u_dcg
        if (same) then
            call t%check('plan cg: the same directions: the same criterion to 1 %', &
                         abs(crit_c/crit_t - 1.0_dp) < 0.01_dp)
        else
            call t%check('plan cg: other directions than the tensor''s plan: a lower '// &
                         'criterion', crit_c < crit_t)
        end if
    contains
        !> The fit with the mass centre of the plan's hangs, made with the truth (DCG) and
        !! noise (stream seed).
        subroutine fit_plan(pl, seed, fit)
            type(tensor_plan_t), intent(in) :: pl
            integer, intent(in) :: seed
            type(tensor_fit_t), intent(out) :: fit
            type(tensor_problem_t) :: pr
            type(rng_t) :: g
            real(dp) :: per(N), gd(3, N), jz(3, 3)
            integer :: k, m
            jz = 0.0_dp
            g = rng_stream(seed, 0)
            do k = 1, N
                call made_period(bd, DCG, 0.0_dp, [0.0_dp, 0.0_dp, 0.0_dp], jz, pl%up(:, k), &
                                 pl%along(:, k), per(k), gd(:, k), st)
                if (st%code /= STATUS_OK) exit
                per(k) = per(k) + UT*rng_normal(g)
                do m = 1, 3
                    gd(m, k) = gd(m, k) + UA*deg*rng_normal(g)
                end do
            end do
            if (st%code == STATUS_OK) then
                call lab_problem(d, bd, pl%up, pl%along, per, pr, gd)
                call fit_of(pr, fit, st)
            end if
            call t%check('plan cg: a table of the plan''s hangs fitted: '//msg_of(st), &
                         st%code == STATUS_OK)
        end subroutine fit_plan
    end subroutine test_plan_cg

    !> plan_add = 3 on a table of six hangs (faces and edges): three directions not in the
    !! table, and a trace of table and additions below the table's alone and below that of
    !! the table with its own first three hangs timed again; through the executable, the
    !! added hangs numbered after the table's.
    subroutine test_plan_add(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        type(body_t) :: bd
        type(deck_t) :: d
        type(tensor_problem_t) :: prob
        type(tensor_plan_t) :: plan
        type(status_t) :: st
        real(dp) :: ups(3, 9), als(3, 9), per(6), gd(3), jz(3, 3), tr6, tr9
        real(dp), parameter :: UT = 1.0e-3_dp
        character(len=:), allocatable :: tab, dir
        integer :: k, j, ex
        logical :: fresh, l1, l2, l3
        bd%x = test_tensor()
        jz = 0.0_dp
        call nine_hangs(ups, als)
        d = lab_deck(bd, UT, 0.1_dp)
        tab = 'hang up_x up_y up_z along_x along_y along_z period'//NL
        do k = 1, 6
            call made_period(bd, [0.0_dp, 0.0_dp, 0.0_dp], 0.0_dp, [0.0_dp, 0.0_dp, 0.0_dp], &
                             jz, ups(:, k), als(:, k), per(k), gd, st)
            tab = tab//itoa(k)//' '//num3(ups(:, k))//' '//num3(als(:, k))//' '//num(per(k))//NL
        end do
        call lab_problem(d, bd, ups(:, 1:6), als(:, 1:6), per, prob)
        call plan_hangs(prob, prob%hangs(1), UT, bd%x, 3, plan, st, prob%hangs, &
                        [(UT, k=1, 6)])
        call t%check('plan add: made: '//msg_of(st), st%code == STATUS_OK .and. plan%n == 3)
        if (st%code /= STATUS_OK) return
        fresh = .true.
        do k = 1, 3
            do j = 1, 6
                if (abs(dot_product(plan%up(:, k), ups(:, j))) > 1.0_dp - 1.0e-9_dp) &
                    fresh = .false.
            end do
        end do
        call design_trace(prob, prob%hangs(1), UT, bd%x, ups(:, 1:6), als(:, 1:6), tr6, st)
        call design_trace(prob, prob%hangs(1), UT, bd%x, reshape([ups(:, 1:6), ups(:, 1:3)], &
                          [3, 9]), reshape([als(:, 1:6), als(:, 1:3)], [3, 9]), tr9, st)
        write (*, '(a,3es11.3)') '   trace: table alone, table + 3 planned, table + its faces '// &
            'again ', tr6, plan%trace, tr9
        call t%check('plan add: three new directions', fresh)
        call t%check('plan add: the trace below the table''s and below repeating its faces', &
                     plan%trace < tr6 .and. plan%trace < tr9)
        dir = SCR//'/plan_add'
        call write_text(dir//'.txt', tab)
        call write_text(dir//'.nml', "&scene analyses = 'tensor' /"//NL// &
            '&suspension b = 0.5, b_prime = 0.4, l = 1.2, l_prime = 1.2, g = 9.80665 /'//NL// &
            '&body mass = 3.0, inertia = 0.08, 0.11, 0.14, cg_depth = 0.1, cg_offset = 0 /'//NL// &
            "&tensor hangs = 'plan_add.txt', u_period = 1e-3, u_direction = 0.1, plan_add = 3 /"//NL)
        call execute_command_line('rm -rf '//dir//' && mkdir -p '//dir//' && '//exe//' '// &
            dir//'.nml --out '//dir//' > '//dir//'.stdout 2> '//dir//'.stderr', exitstat=ex)
        l1 = file_has(dir//'/plan_add.plan.csv', '7,')
        l2 = file_has(dir//'/plan_add.plan.csv', '9,')
        l3 = count_lines(dir//'/plan_add.plan.csv') == 4 + 3
        call t%check('plan add: exe: exit 0 (got '//itoa(ex)//'), hangs 7, 8, 9 added', &
                     ex == 0 .and. l3)
        call t%check('plan add: exe: numbered after the table''s', l1 .and. l2)
    end subroutine test_plan_add

    ! ------------------------------------------------------------------ refusals

    !> Each new key out of its range: one line naming it, exit 2, no file.
    subroutine test_keys(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        call one('neg_mass', 'fixture_mass = -0.1', 'fixture_mass')
        call one('asym', 'fixture_inertia = 1e-3, 2e-4, 0, 0, 1e-3, 0, 0, 0, 1e-3', &
                 'fixture_inertia')
        call one('frame', "fixture_mass = 0.1, fixture_frame = 'table'", 'fixture_frame')
        call one('neg_u', 'fixture_mass = 0.1, u_fixture_cg = -1e-3', 'u_fixture_*')
        call one('estimate', "estimate = 'tensor mass'", 'estimate')
        call one('u_att', "estimate = 'tensor cg', u_attitude = 0", 'u_attitude')
        call one('plan_add', 'plan_add = 30', 'plan_add')
        call one('plan_both', 'plan = 9, plan_add = 3', 'plan_add')
    contains
        subroutine one(label, keys, word)
            character(len=*), intent(in) :: label, keys, word
            character(len=:), allocatable :: dir
            integer :: ex
            logical :: l1, l2, l3
            dir = SCR//'/key_'//label
            call write_text(dir//'.txt', 'hang up_x up_y up_z along_x along_y along_z '// &
                'period'//NL//'1 1 0 0 0 1 0 1.6'//NL)
            call write_text(dir//'.nml', "&scene analyses = 'tensor' /"//NL// &
                '&suspension b = 0.5, b_prime = 0.4, l = 1.2, l_prime = 1.2, g = 9.80665 /'// &
                NL//'&body mass = 3.0, inertia = 0.08, 0.11, 0.14, cg_depth = 0.1 /'//NL// &
                "&tensor hangs = 'key_"//label//".txt', "//keys//" /"//NL)
            call execute_command_line('rm -rf '//dir//' && mkdir -p '//dir//' && '//exe// &
                ' '//dir//'.nml --out '//dir//' > '//dir//'.stdout 2> '//dir//'.stderr', &
                exitstat=ex)
            l1 = count_lines(dir//'.stderr') == 1
            l2 = file_has(dir//'.stderr', word)
            l3 = empty_dir(dir)
            call t%check('keys '//label//': exit 2 (got '//itoa(ex)//'), one line naming '// &
                         word//', no file', ex == 2 .and. l1 .and. l2 .and. l3)
        end subroutine one
    end subroutine test_keys

    ! ------------------------------------------------------------------ text

    !> The real of `key = a` (huge when absent).
    function kv1(path, key) result(v)
        character(len=*), intent(in) :: path, key
        real(dp) :: v
        real(dp) :: w(6)
        w = kv6(path, key, 1)
        v = w(1)
    end function kv1

    !> The first n (6 by default) reals of `key = a, b, ...` (huge when absent).
    function kv6(path, key, n) result(v)
        character(len=*), intent(in) :: path, key
        integer, intent(in), optional :: n
        real(dp) :: v(6)
        character(len=1024) :: line
        integer :: u, ios, m
        m = 6
        if (present(n)) m = n
        v = huge(1.0_dp)
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        do while (ios == 0)
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (index(line, key//' = ') == 1) then
                read (line(len(key) + 4:), *, iostat=ios) v(1:m)
                if (ios /= 0) v = huge(1.0_dp)
                exit
            end if
        end do
        close (u)
    end function kv6

    !> The three reals of `key = a, b, c` in a key = value file (huge when absent).
    function kv3(path, key) result(v)
        character(len=*), intent(in) :: path, key
        real(dp) :: v(3)
        character(len=1024) :: line
        integer :: u, ios
        v = huge(1.0_dp)
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        do while (ios == 0)
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (index(line, key//' = ') == 1) then
                read (line(len(key) + 4:), *, iostat=ios) v
                if (ios /= 0) v = huge(1.0_dp)
                exit
            end if
        end do
        close (u)
    end function kv3

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

end module test_tensor_lab
