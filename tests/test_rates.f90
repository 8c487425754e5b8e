!> Tests of records of the body's three rates (&measurement quantity = 'rates'): the rates
!! an instrument fixed on the body reads, as the model predicts them, against central
!! differences of the model's own pose in time (any axes, principal axes turned in the
!! body); their sensitivities to I2, I3, cg_depth and the release's tilt and sway against
!! differences of whole runs; a 3-axis gyro record of a release that tilts and sways (made
!! here: the model plus noise and bias) fitted for I1, I2, I3, cg_depth, tilt, sway and the
!! three biases, each truth in its 95 % interval; a pure-torsion record asked for I2
!! refused naming it; the four columns of a gyro export read by name.
module test_rates
    use kinds, only: dp, deg
    use status, only: status_t
    use text, only: sci
    use testing, only: tester_t, msg_of, write_text, run_cmd => run, fresh_dir, file_has, &
        exists, kv_real, rig_deck
    use testing_records, only: lab_rig, turned_rig, video_rig, make_gyro, make_track, &
        pose_states, check_sens, check_release_fit
    use deck, only: deck_t, read_deck
    use rig, only: rig_t, start_t, accuracy_t
    use geometry, only: pendulum_t, frame, body_pose
    use bifilar_model, only: NSTATE
    use record_fit, only: record_model
    use measure_groups, only: parse_axes
    use inputs, only: input_value
    use records, only: record_t
    use identify, only: identify_result_t, identify_record
    use random, only: rng_t, rng_stream, rng_normal
    implicit none
    private

    public :: run_rates_tests

    character(len=*), parameter :: DIR = 'build/test_rates'

contains

    subroutine run_rates_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        if (t%want('rates: the instrument''s rates against differences of the model''s pose')) &
            call test_pose(t)
        if (t%want('rates: sensitivities to I2, I3, cg_depth, tilt, sway against differences')) &
            call test_sens(t)
        if (t%want('rates: a 3-axis gyro record gives I1, I2, I3 and cg_depth')) call test_goal(t)
        if (t%want('rates: a pure-torsion record cannot give I2')) call test_refusal(t, exe)
        if (t%want('rates: t0 estimated, and a release turned the other way')) &
            call test_t0_sign(t)
        if (t%want('rates: a tracked point (quantity point) released either way, t0 estimated')) &
            call test_point_sign(t)
        if (t%want('rates: a phone''s gyro export through the program')) call test_export(t, exe)
    end subroutine run_rates_tests

    !> The model's rates (record_model with axes) at 25 times against the rates of the
    !! model's own pose: the body's principal axes b_i (b = btilde n, eq. (11)) from the
    !! states of a run at t +- h, omega . b_1 = b_2' . b_3 and cyclically, by central
    !! differences (h = 1e-4 tau, error about 1e-9 of the rates), read by the instrument
    !! (record_axes 'z -x y'), on the laboratory rig with principal axes turned in the body.
    subroutine test_pose(t)
        type(tester_t), intent(inout) :: t
        integer, parameter :: NT = 25
        real(dp), parameter :: H = 1.0e-4_dp
        type(rig_t) :: rg
        type(start_t) :: st
        type(accuracy_t) :: acc
        type(pendulum_t) :: p
        type(status_t) :: stat
        real(dp), allocatable :: ys(:, :)
        real(dp) :: axes(3, 3), ts(NT), taus(0:3*NT - 1), vals(3*NT)
        real(dp) :: s, bp(3, 3), bm(3, 3), b0(3, 3), db(3, 3), om(3), want(3), worst, big
        integer :: i, k
        logical :: ok
        call turned_rig(rg, st, acc)
        acc%rtol = 1.0e-12_dp
        acc%atol = 1.0e-14_dp
        call parse_axes('z -x y', axes, ok)
        call t%check('rates: record_axes ''z -x y'' read', ok)
        call t%check('rates: record_axes ''x x y'' refused', .not. parse_ok('x x y'))
        call t%check('rates: record_axes ''x y'' refused', .not. parse_ok('x y'))
        s = sqrt(rg%g/rg%b_prime)
        do i = 1, NT
            ts(i) = 0.37_dp*i
            taus(3*(i - 1):3*(i - 1) + 2) = ts(i)*s + [-H, 0.0_dp, H]
        end do
        call record_model(rg, st, acc, ts, 0.0_dp, .true., vals, stat, axes)
        call t%check('rates: the model''s rates'//msg_of(stat), stat%code == 0)
        if (stat%code /= 0) return
        call pose_states(rg, st, acc, taus, p, ys, stat)
        call t%check('rates: the run of the pose'//msg_of(stat), stat%code == 0)
        if (stat%code /= 0) return
        worst = 0.0_dp
        big = 0.0_dp
        do i = 1, NT
            bm = axes_at(ys(:, 3*(i - 1)))
            b0 = axes_at(ys(:, 3*(i - 1) + 1))
            bp = axes_at(ys(:, 3*(i - 1) + 2))
            db = (bp - bm)/(2.0_dp*H)
            ! rows: b_i in n; omega . b_1 = b_2' . b_3, omega . b_2 = b_3' . b_1, ...
            om = [dot_product(db(2, :), b0(3, :)), dot_product(db(3, :), b0(1, :)), &
                  dot_product(db(1, :), b0(2, :))]
            want = matmul(axes, om)*s
            do k = 1, 3
                worst = max(worst, abs(vals((k - 1)*NT + i) - want(k)))
                big = max(big, abs(want(k)))
            end do
        end do
        call t%check_close('rates: rates against differences of the pose, worst error '// &
                           'over the largest rate', worst/big, 0.0_dp, 0.0_dp, 1.0e-7_dp)
        ! the horizontal axes move: the release tilts and sways
        call t%check('rates: the tilted release turns the body about a horizontal axis', &
                     maxval(abs(vals(2*NT + 1:3*NT))) > 1.0e-3_dp*big .and. &
                     maxval(abs(vals(1:NT))) > 1.0e-3_dp*big)
    contains
        function axes_at(y) result(b)
            real(dp), intent(in) :: y(NSTATE)
            real(dp) :: b(3, 3), n(3, 3)
            call frame(body_pose(y(1), y(4), y(5), 0.0_dp), n)
            b = matmul(p%btilde, n)
        end function axes_at
        logical function parse_ok(text)
            character(len=*), intent(in) :: text
            real(dp) :: a(3, 3)
            call parse_axes(text, a, parse_ok)
        end function parse_ok
    end subroutine test_pose

    !> The derivatives of the three rates (record_model_sens: forward sensitivities) along
    !! I1, I2, I3, cg_depth, tilt and sway against central differences of whole runs,
    !! extrapolated (error h^4), at 41 samples over 8 s: within 1e-5 of the largest rate
    !! for a change of each quantity by its size (the sensitivities ride outside the
    !! integrator's error control).
    subroutine test_sens(t)
        type(tester_t), intent(inout) :: t
        integer, parameter :: NT = 41, NQ = 6
        character(len=16), parameter :: NAMES(NQ) = [character(len=16) :: 'I1', 'I2', 'I3', &
            'cg_depth', 'tilt', 'sway']
        type(rig_t) :: rg
        type(start_t) :: st
        type(accuracy_t) :: acc
        real(dp) :: ts(NT), xs(NQ), axes(3, 3)
        integer :: i
        logical :: ok
        call lab_rig(rg, st, acc)
        acc%rtol = 1.0e-11_dp
        acc%atol = 1.0e-13_dp
        call parse_axes('aligned', axes, ok)
        do i = 1, NT
            ts(i) = 0.2_dp*(i - 1)
        end do
        xs = [rg%inertia, input_value(rg, st, 'cg_depth'), st%tilt, st%sway]
        call check_sens(t, 'rates', 'rate', rg, st, acc, ts, NAMES, xs, axes=axes)
    end subroutine test_sens

    !> A 3-axis gyro record (100 Hz, 30 s; noise 0.003 rad/s, biases of a few mrad/s on each
    !! axis) of the laboratory rig released from 30 degrees with 2 degrees of tilt and 1 cm
    !! of sway, fitted from start values 2 % (I1), 5 to 8 % (I2, I3) and 9 mm (cg_depth) off,
    !! no tilt, no sway: I1 within 0.1 %, cg_depth within 2 mm, I2 and I3 within 3 %, each
    !! truth inside its 95 % interval (k u); the output says what the record determines.
    subroutine test_goal(t)
        type(tester_t), intent(inout) :: t
        integer, parameter :: N = 3001
        real(dp), parameter :: SIGMA = 0.003_dp, BIAS(3) = [0.004_dp, -0.006_dp, 0.003_dp]
        type(rig_t) :: rg
        type(start_t) :: st
        type(accuracy_t) :: acc
        type(deck_t) :: d
        type(record_t) :: rec
        type(identify_result_t) :: res
        type(status_t) :: stat
        real(dp) :: axes(3, 3), truth(9), cg, cg_off
        character(len=9) :: names(9) = [character(len=9) :: 'I1', 'I2', 'I3', 'cg_depth', &
            'tilt', 'sway', 'bias', 'bias_y', 'bias_z']
        integer :: i, k, j
        logical :: ok
        call fresh_dir(DIR)
        call lab_rig(rg, st, acc)
        call parse_axes('aligned', axes, ok)
        call make_gyro(rg, st, acc, [(0.01_dp*(i - 1), i=1, N)], 0.0_dp, axes, BIAS, &
                       [1.0_dp, 1.0_dp, 1.0_dp], SIGMA, 7, 0, rec, stat)
        call t%check('rates: the record made'//msg_of(stat), stat%code == 0)
        if (stat%code /= 0) return
        cg = input_value(rg, st, 'cg_depth')
        cg_off = input_value(rg, st, 'cg_offset')
        call write_text(DIR//'/goal.nml', rig_deck('3-axis gyro', '1.18', 'inertia = 0.0502, '// &
            '0.0670, 0.0284, cg_depth = 0.14, cg_offset = '//sci(cg_off, 6)//', '// &
            'sway_depth = 0.30')//'&start mode = ''raised'', amplitude = 30.0 /'//new_line('a')// &
            '&measurement record = ''goal.dat'', quantity = ''rates'', '// &
            'estimate = ''I1 I2 I3 cg_depth tilt sway bias'', u_inertia = 0.005, 0.005, '// &
            'u_cg_depth = 0.02 /'//new_line('a'))
        call read_deck(DIR//'/goal.nml', d, stat)
        call t%check('rates: the goal deck'//msg_of(stat), stat%code == 0)
        if (stat%code /= 0) return
        call identify_record(d, rec, res, stat)
        call t%check('rates: the 3-axis fit'//msg_of(stat), stat%code == 0)
        if (stat%code /= 0) return
        truth = [rg%inertia, cg, st%tilt, st%sway, BIAS]
        call t%check('rates: nine parameters estimated', res%np == 9)
        if (res%np /= 9) return
        do j = 1, 9
            k = findloc(res%names(1:res%np), names(j), 1)
            call t%check('rates: '//trim(names(j))//' estimated', k > 0)
            if (k == 0) cycle
            print '(a,3es14.6)', '   '//names(j)//' estimate, truth, u: ', res%p(k), truth(j), &
                res%u_p(k)
            call t%check('rates: '//trim(names(j))//'''s truth within its 95 % interval', &
                         abs(res%p(k) - truth(j)) <= max(res%k, 1.96_dp)*res%u_p(k))
        end do
        call t%check_close('rates: I1 within 0.1 %', res%i1, rg%inertia(1), 1.0e-3_dp, 0.0_dp)
        call t%check_close('rates: I2 within 3 %', res%p(findloc(res%names, 'I2', 1)), &
                           rg%inertia(2), 3.0e-2_dp, 0.0_dp)
        call t%check_close('rates: I3 within 3 %', res%p(findloc(res%names, 'I3', 1)), &
                           rg%inertia(3), 3.0e-2_dp, 0.0_dp)
        call t%check_close('rates: cg_depth within 2 mm', res%p(findloc(res%names, &
                           'cg_depth', 1)), cg, 0.0_dp, 2.0e-3_dp)
        call t%check('rates: what the record determines: correlations and condition', &
                     res%determined .and. res%correlation_max > 0.0_dp .and. &
                     res%correlation_max < 1.0_dp .and. res%condition >= 1.0_dp)
        print '(a,es10.3,a,es10.3,a)', '   correlation_max ', res%correlation_max, &
            ' ('//trim(res%correlation_pair)//'), condition ', res%condition, ''
    end subroutine test_goal

    !> Four 3-axis records of the laboratory rig (no tilt, no sway), t0 estimated, the
    !! deck's amplitude the turn's size: one held still 2 s before its release from 30
    !! degrees and one held 2 s before its release from -20 degrees (turned the other way),
    !! both fitted for I1, t0 and the biases; one released at t = 0 from -30 degrees (no
    !! bias) and one at t = 0 from 30 degrees, both fitted for I1 and t0 (the release at the
    !! record's first sample, not the turning point half a period on).  Each I1 and t0
    !! within U of the truth (the model released the record's way: the tilt and sway rates
    !! do not mirror).
    subroutine test_t0_sign(t)
        type(tester_t), intent(inout) :: t
        integer, parameter :: N = 1201, NC = 4
        real(dp), parameter :: SIGMA = 0.003_dp, BIAS(3) = [0.004_dp, -0.006_dp, 0.003_dp]
        real(dp), parameter :: T0S(NC) = [2.0_dp, 2.0_dp, 0.0_dp, 0.0_dp], &
            AMPS(NC) = [30.0_dp, -20.0_dp, -30.0_dp, 30.0_dp], &
            BIASED(NC) = [1.0_dp, 1.0_dp, 0.0_dp, 0.0_dp]
        character(len=*), parameter :: WHAT(NC) = [character(len=24) :: 'held, t0', &
            'the other way', 'the other way at t = 0', 'released at t = 0']
        character(len=*), parameter :: EST(NC) = [character(len=12) :: 'I1 t0 bias', &
                                                  'I1 t0 bias', 'I1 t0', 'I1 t0']
        type(rig_t) :: rg
        type(start_t) :: st
        type(accuracy_t) :: acc
        type(record_t) :: rec
        type(status_t) :: stat
        real(dp) :: axes(3, 3)
        integer :: i, c
        logical :: ok
        character(len=16) :: amp
        call fresh_dir(DIR//'/t0')
        call lab_rig(rg, st, acc)
        st%tilt = 0.0_dp
        st%sway = 0.0_dp
        call parse_axes('aligned', axes, ok)
        do c = 1, NC
            st%amplitude = AMPS(c)
            call make_gyro(rg, st, acc, [(0.01_dp*(i - 1), i=1, N)], T0S(c), axes, &
                           BIASED(c)*BIAS, [1.0_dp, 1.0_dp, 1.0_dp], SIGMA, 9, c, rec, stat)
            call t%check('rates: '//trim(WHAT(c))//': the record made'//msg_of(stat), &
                         stat%code == 0)
            if (stat%code /= 0) return
            ! the deck gives the size of the turn; its way is the record's
            write (amp, '(f6.1)') abs(AMPS(c))
            call write_text(DIR//'/t0/t0.nml', rig_deck('3-axis gyro', '1.18', 'inertia = '// &
                '0.049, 0.0630, 0.0304, r = 0.25, lambda = 0.64, sway_depth = 0.30')// &
                '&start mode = ''raised'', amplitude = '//trim(adjustl(amp))//' /'// &
                new_line('a')//'&measurement record = ''t0.dat'', quantity = ''rates'', '// &
                'estimate = '''//trim(EST(c))//''' /'//new_line('a'))
            call check_release_fit(t, WHAT(c), DIR//'/t0/t0.nml', rec, rg%inertia(1), T0S(c), ok)
            if (.not. ok) return
        end do
    end subroutine test_t0_sign

    !> A tracked point's video track (quantity 'point', the point 5 cm off the axis, seen
    !! from below: one coordinate odd in theta4, the other even) held 1 s before its release
    !! from 20 degrees, and the same from -20 degrees (turned the other way; the deck's
    !! amplitude the turn's size), fitted for I1, t0 and the two offsets: each I1 and t0
    !! within U of the truth (the model released the record's way, not mirrored).
    subroutine test_point_sign(t)
        type(tester_t), intent(inout) :: t
        integer, parameter :: N = 901
        real(dp), parameter :: QV(3) = [0.0_dp, 0.05_dp, 0.0_dp], T0 = 1.0_dp
        real(dp), parameter :: AMPS(2) = [20.0_dp, -20.0_dp]
        character(len=*), parameter :: WHAT(2) = [character(len=16) :: 'point, held', &
                                                  'point, other way']
        type(rig_t) :: rg
        type(start_t) :: st
        type(accuracy_t) :: acc
        type(record_t) :: rec
        type(status_t) :: stat
        integer :: i, c
        logical :: ok
        call fresh_dir(DIR//'/pt')
        call video_rig(rg, st, acc)
        do c = 1, 2
            st%amplitude = AMPS(c)
            call make_track(rg, st, acc, [((i - 1)/60.0_dp, i=1, N)], T0, QV, 17, c, rec, stat)
            call t%check('rates: '//trim(WHAT(c))//': the track made'//msg_of(stat), &
                         stat%code == 0)
            if (stat%code /= 0) return
            ! the record's value: the coordinate with the larger swing (the odd one)
            if (maxval(rec%vs(N + 1:)) - minval(rec%vs(N + 1:)) > maxval(rec%v) - &
                minval(rec%v)) rec%v = rec%vs(N + 1:)
            call write_text(DIR//'/pt/pt.nml', rig_deck('video', '1.20', 'inertia = 0.0522, '// &
                '0.0630, 0.0304, r = 0.20, lambda = 0.0, sway_depth = 0.30')// &
                '&start mode = ''raised'', amplitude = 20.0 /'//new_line('a')// &
                '&measurement record = ''pt.dat'', quantity = ''point'', record_point = 0, '// &
                '0.05, 0, record_scale = 5.0e-4, estimate = ''I1 t0 bias'' /'//new_line('a'))
            call check_release_fit(t, WHAT(c), DIR//'/pt/pt.nml', rec, rg%inertia(1), T0, ok)
            if (.not. ok) return
        end do
    end subroutine test_point_sign

    !> A record of pure torsion (no tilt, no sway, a symmetric rig) asked for I1 and I2:
    !! refused with exit 2, one line naming I2, no output.
    subroutine test_refusal(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        integer, parameter :: N = 1001
        type(rig_t) :: rg
        type(start_t) :: st
        type(accuracy_t) :: acc
        type(status_t) :: stat
        real(dp) :: vals(3*N), tt(N), axes(3, 3)
        character(len=:), allocatable :: text, deck
        character(len=64) :: line
        integer :: i, ex, iq
        logical :: ok
        character(len=5), parameter :: QS(2) = ['rate ', 'rates']
        call fresh_dir(DIR//'/refuse')
        call lab_rig(rg, st, acc)
        rg%l_prime = rg%l
        rg%lambda = atan2(0.15_dp, 0.2_dp)
        rg%r = sqrt(0.15_dp**2 + 0.2_dp**2)
        st%tilt = 0.0_dp
        st%sway = 0.0_dp
        acc%rtol = 1.0e-10_dp
        acc%atol = 1.0e-12_dp
        call parse_axes('aligned', axes, ok)
        do i = 1, N
            tt(i) = 0.01_dp*(i - 1)
        end do
        call record_model(rg, st, acc, tt, 0.0_dp, .true., vals, stat, axes)
        call t%check('rates: the pure-torsion record'//msg_of(stat), stat%code == 0)
        if (stat%code /= 0) return
        text = '# t wx wy wz'//new_line('a')
        do i = 1, N
            write (line, '(f8.3,3es18.9)') tt(i), vals(i), vals(N + i), vals(2*N + i)
            text = text//trim(line)//new_line('a')
        end do
        call write_text(DIR//'/refuse/torsion.dat', text)
        do iq = 1, 2
            deck = rig_deck('pure torsion', '1.20', 'inertia = 0.050, 0.063, 0.0304, '// &
                'r = 0.25, lambda = 0.6435', .false.)//'&start mode = ''raised'', '// &
                'amplitude = 30.0 /'// &
                new_line('a')//'&measurement record = ''torsion.dat'', quantity = '''// &
                trim(QS(iq))//''', estimate = ''I1 I2'''
            if (iq == 1) deck = deck//', record_columns = 1, 2'
            if (iq == 1) deck = deck//' /'//new_line('a')
            if (iq == 2) deck = deck//', record_columns = 1, 2, 3, 4 /'//new_line('a')
            ! the vertical rate W = -omega . b_1 for quantity 'rate': column 2 negated
            if (iq == 1) then
                text = '# t W'//new_line('a')
                do i = 1, N
                    write (line, '(f8.3,es18.9)') tt(i), -vals(i)
                    text = text//trim(line)//new_line('a')
                end do
                call write_text(DIR//'/refuse/torsion_w.dat', text)
                deck = deck(1:index(deck, 'torsion.dat') - 1)//'torsion_w.dat'// &
                    deck(index(deck, 'torsion.dat') + 11:)
            end if
            call write_text(DIR//'/refuse/torsion.nml', deck)
            ex = run_cmd(exe//' '//DIR//'/refuse/torsion.nml --out '//DIR//'/refuse/out', &
                         DIR//'/refuse')
            call t%check('rates: pure torsion, quantity '''//trim(QS(iq))//''', I1 I2: '// &
                         'exit 2', ex == 2)
            call t%check('rates: pure torsion, quantity '''//trim(QS(iq))//''': the line '// &
                         'names I2', file_has(DIR//'/refuse/stderr', 'cannot give I2'))
            call t%check('rates: pure torsion, quantity '''//trim(QS(iq))//''': no output', &
                         .not. exists(DIR//'/refuse/out/torsion.identify'))
        end do
    end subroutine test_refusal

    !> A phone's gyro export (phyphox's header: time, the three axes, their magnitude; the
    !! phone flat on the body, its z up: record_axes = 'y z -x') of the laboratory rig's
    !! tilted and swayed release, 20 s at 100 Hz with noise and bias, through the program:
    !! the three axes taken by their names (no record_columns), I1, I2, I3, cg_depth found,
    !! the output says quantity 'rates' and what the record determines; the same record
    !! with a unit conflict (record_units = 'deg/s') refused.
    subroutine test_export(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        integer, parameter :: N = 2001
        character(len=*), parameter :: AX = 'y z -x'
        type(rig_t) :: rg
        type(start_t) :: st
        type(accuracy_t) :: acc
        type(status_t) :: stat
        type(rng_t) :: g
        real(dp) :: vals(3*N), tt(N), axes(3, 3), w(3), cg
        character(len=:), allocatable :: text, deck
        character(len=120) :: line
        integer :: i, k, ex
        logical :: ok
        call fresh_dir(DIR//'/export')
        call lab_rig(rg, st, acc)
        acc%rtol = 1.0e-10_dp
        acc%atol = 1.0e-12_dp
        call parse_axes(AX, axes, ok)
        do i = 1, N
            tt(i) = 0.01_dp*(i - 1)
        end do
        call record_model(rg, st, acc, tt, 0.0_dp, .true., vals, stat, axes)
        call t%check('rates: the export''s record'//msg_of(stat), stat%code == 0)
        if (stat%code /= 0) return
        g = rng_stream(11, 0)
        text = '"Time (s)","Gyroscope x (rad/s)","Gyroscope y (rad/s)","Gyroscope z '// &
            '(rad/s)","Absolute (rad/s)"'//new_line('a')
        do i = 1, N
            do k = 1, 3
                w(k) = vals((k - 1)*N + i) + 0.002_dp*k + 0.003_dp*rng_normal(g)
            end do
            write (line, '(f0.3,4(",",es16.8))') tt(i), w, norm2(w)
            text = text//trim(line)//new_line('a')
        end do
        call write_text(DIR//'/export/phone.csv', text)
        cg = input_value(rg, st, 'cg_depth')
        deck = rig_deck('phone gyro', '1.18', 'inertia = 0.0505, 0.066, 0.029, r = 0.25, '// &
            'lambda = 0.64')//'&start mode = ''raised'', amplitude = 30.0 /'//new_line('a')// &
            '&measurement record = ''phone.csv'', quantity = ''rates'', record_axes = '// &
            ''''//AX//''', estimate = ''I1 I2 I3 cg_depth tilt sway bias'', u_mass = 0.001 /'// &
            new_line('a')
        call write_text(DIR//'/export/phone.nml', deck)
        ex = run_cmd(exe//' '//DIR//'/export/phone.nml --out '//DIR//'/export/out', DIR//'/export')
        call t%check('rates: the phone''s export through the program: exit 0', ex == 0)
        if (ex /= 0) return
        call t%check('rates: the output says quantity ''rates''', &
                     file_has(DIR//'/export/out/phone.identify', 'quantity = rates'))
        call t%check('rates: the output says u against the prior', &
                     file_has(DIR//'/export/out/phone.identify', 'u_prior_I2 = none'))
        call t%check('rates: the output says the largest correlation', &
                     file_has(DIR//'/export/out/phone.identify', 'correlation_max = '))
        call t%check('rates: the output says the condition', &
                     file_has(DIR//'/export/out/phone.identify', 'condition = '))
        call t%check_close('rates: the export''s I2 within 3 %', &
                           kv_real(DIR//'/export/out/phone.identify', 'I2'), rg%inertia(2), &
                           3.0e-2_dp, 0.0_dp)
        call t%check_close('rates: the export''s cg_depth within 2 mm', &
                           kv_real(DIR//'/export/out/phone.identify', 'cg_depth'), cg, &
                           0.0_dp, 2.0e-3_dp)
        ! a unit conflict between the columns' names and record_units: one line, no output
        call write_text(DIR//'/export/conflict.nml', deck(1:index(deck, ', u_mass') - 1)// &
                        ', record_units = ''deg/s'' /'//new_line('a'))
        call fresh_dir(DIR//'/export/out2')
        ex = run_cmd(exe//' '//DIR//'/export/conflict.nml --out '//DIR//'/export/out2', &
                     DIR//'/export')
        call t%check('rates: a unit conflict refused (exit 2)', ex == 2)
        call t%check('rates: a unit conflict leaves no output', &
                     .not. exists(DIR//'/export/out2/conflict.identify'))
    end subroutine test_export

end module test_rates
