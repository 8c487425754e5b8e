!> Tests of records of a tracked point (&measurement quantity = 'point', a video's track):
!! the point's position the model predicts against an independent computation from the
!! model's pose (the mass centre of geometry's mass_centre plus the point turned by the
!! body's axes), its gradient against central differences of the position in the chart
!! state and its velocity along the motion against differences in time; its sensitivities
!! against differences of whole runs; a video track (made here: the model in pixels, a
!! camera origin, noise) of a point 5 cm off the axis of a release that sways at 10 % of
!! the torsion's amplitude, fitted for I1, sway, the camera's origin and the scale: I1
!! within 0.05 %, the scale within its interval, also as a track's file through the
!! program (seconds or frame numbers), and the bias of the same track read the old way
!! (the point's angle about the axis, fitted as theta4 of one axis) larger; misuses of
!! the keys refused with one line.  The same release seen from the side (record_view =
!! 'side') as a track's file through the program: I1 within 0.05 % and within its U.
module test_point
    use kinds, only: dp, deg, pi
    use status, only: status_t
    use text, only: sci
    use testing, only: tester_t, msg_of, write_text, run_cmd => run, fresh_dir, file_has, &
        exists, count_lines, kv_real, replaced, rig_deck
    use testing_records, only: lab_rig, turned_rig, video_rig, make_gyro, make_track, &
        write_track, pose_states, check_sens, TRACK_SCALE, TRACK_ORIGIN
    use deck, only: deck_t, read_deck
    use rig, only: rig_t, start_t, accuracy_t, make_pendulum
    use geometry, only: pendulum_t, frame, body_pose, mass_centre, body_axes, cable_direction
    use bifilar_model, only: NSTATE
    use record_fit, only: record_model, point_position, point_gradient, VIEW_BELOW, VIEW_SIDE
    use inputs, only: input_value
    use records, only: record_t
    use measure_groups, only: parse_axes
    use identify, only: identify_result_t, identify_record
    implicit none
    private

    public :: run_point_tests

    character(len=*), parameter :: DIR = 'build/test_point'
    !> The tracked point in the body's principal axes from the mass centre (m)
    real(dp), parameter :: QPT(3) = [0.03_dp, 0.05_dp, -0.02_dp]

contains

    subroutine run_point_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        if (t%want('point: the model''s point against its pose, gradient and velocity')) &
            call test_pose(t)
        if (t%want('point: sensitivities against differences of whole runs')) call test_sens(t)
        if (t%want('point: a video track with sway gives I1 without the sway''s bias')) &
            call test_goal(t, exe)
        if (t%want('point: a side view''s track from its file gives I1 within U')) &
            call test_side(t, exe)
        if (t%want('point: misuses of the keys refused with one line')) call test_refusal(t, exe)
        if (t%want('point: estimate = ''scale'' with quantity ''rates'': three scales')) &
            call test_rates_scale(t)
    end subroutine run_point_tests

    !> The model's point (record_model with point, both views) at 25 times against the
    !! point computed here from the states of a run: P = b' R*(C, n) + q_i b_i, C = B + L e
    !! from the cable's direction, R* by mass_centre, b = body_axes, less P at zero angles
    !! (within 1e-9 of the largest excursion: the runs are the same); point_gradient
    !! against central differences of point_position in each component of the state; the
    !! point's velocity, the gradient times the state's rate, against central differences in
    !! time of the model's points (h = 1e-4 s).
    subroutine test_pose(t)
        type(tester_t), intent(inout) :: t
        integer, parameter :: NT = 25
        real(dp), parameter :: H = 1.0e-4_dp
        type(rig_t) :: rg
        type(start_t) :: st
        type(accuracy_t) :: acc
        type(pendulum_t) :: p
        type(status_t) :: stat
        real(dp) :: ts(NT), taus(0:NT - 1), vb(2*NT), vs(2*NT), vp(2*NT), vm(2*NT)
        real(dp), allocatable :: ys(:, :)
        real(dp) :: s, pos(3), pos0(3), worst, big, wg, wv, gbig
        real(dp) :: g(NSTATE, 2), gfd(NSTATE, 2), y(NSTATE), e(NSTATE), vel(2), tp(NT), tm(NT)
        integer :: i, k
        call turned_rig(rg, st, acc)
        acc%rtol = 1.0e-12_dp
        acc%atol = 1.0e-14_dp
        s = sqrt(rg%g/rg%b_prime)
        do i = 1, NT
            ts(i) = 0.37_dp*i
            taus(i - 1) = ts(i)*s
        end do
        call record_model(rg, st, acc, ts, 0.0_dp, .false., vb, stat, point=QPT)
        if (stat%code == 0) call record_model(rg, st, acc, ts, 0.0_dp, .false., vs, stat, &
                                              point=QPT, view=VIEW_SIDE)
        call t%check('point: the model''s point'//msg_of(stat), stat%code == 0)
        if (stat%code /= 0) return
        call pose_states(rg, st, acc, taus, p, ys, stat)
        call t%check('point: the run of the pose'//msg_of(stat), stat%code == 0)
        if (stat%code /= 0) return
        pos0 = absolute(spread(0.0_dp, 1, NSTATE))
        worst = 0.0_dp
        big = 0.0_dp
        do i = 1, NT
            pos = absolute(ys(:, i - 1)) - pos0
            worst = max(worst, abs(vb(i) - pos(1)), abs(vb(NT + i) - pos(2)), &
                        abs(vs(i) - pos(2)), abs(vs(NT + i) - pos(3)))
            big = max(big, maxval(abs(pos)))
        end do
        call t%check_close('point: the point against the pose''s own (both views), worst '// &
                           'error over the largest excursion', worst/big, 0.0_dp, 0.0_dp, &
                           1.0e-9_dp)
        call t%check('point: the release sways: the point leaves the torsion''s circle', &
                     maxval(abs(vs(NT + 1:2*NT))) > 1.0e-4_dp)
        ! the gradient against differences of the position in the state
        wg = 0.0_dp
        gbig = 0.0_dp
        do i = 1, NT
            y = ys(:, i - 1)
            g = point_gradient(p, rg%b_prime, QPT, VIEW_BELOW, y)
            do k = 1, 5
                e = 0.0_dp
                e(k) = 1.0e-6_dp
                gfd(k, :) = (point_position(p, rg%b_prime, QPT, VIEW_BELOW, y + e) - &
                             point_position(p, rg%b_prime, QPT, VIEW_BELOW, y - e))/2.0e-6_dp
            end do
            gfd(6:, :) = 0.0_dp
            wg = max(wg, maxval(abs(g - gfd)))
            gbig = max(gbig, maxval(abs(g)))
        end do
        call t%check_close('point: the gradient against differences of the position '// &
                           '(worst over the largest)', wg/gbig, 0.0_dp, 0.0_dp, 1.0e-8_dp)
        ! the velocity along the motion: the gradient times the state's rate (per tau, times
        ! s per second) against differences in time of the model's points
        tp = ts + H
        tm = ts - H
        call record_model(rg, st, acc, tp, 0.0_dp, .false., vp, stat, point=QPT)
        if (stat%code == 0) call record_model(rg, st, acc, tm, 0.0_dp, .false., vm, stat, &
                                              point=QPT)
        call t%check('point: the runs in time'//msg_of(stat), stat%code == 0)
        if (stat%code /= 0) return
        wv = 0.0_dp
        big = 0.0_dp
        do i = 1, NT
            y = ys(:, i - 1)
            g = point_gradient(p, rg%b_prime, QPT, VIEW_BELOW, y)
            vel = [dot_product(g(1:5, 1), y(6:10)), dot_product(g(1:5, 2), y(6:10))]*s
            wv = max(wv, abs(vel(1) - (vp(i) - vm(i))/(2.0_dp*H)), &
                     abs(vel(2) - (vp(NT + i) - vm(NT + i))/(2.0_dp*H)))
            big = max(big, maxval(abs(vel)))
        end do
        call t%check_close('point: the velocity against differences in time (worst over '// &
                           'the largest)', wv/big, 0.0_dp, 0.0_dp, 1.0e-6_dp)
    contains
        !> The point from the pose, independently: R* = C + r (s_lam ntilde_1 - c_lam
        !! ntilde_3) in b' units (geometry's mass_centre), plus q_i b_i (m).
        function absolute(yy) result(x)
            real(dp), intent(in) :: yy(NSTATE)
            real(dp) :: x(3), n(3, 3), b(3, 3), c(3), ev(3)
            call frame(body_pose(yy(1), yy(4), yy(5), 0.0_dp), n)
            ev = cable_direction(yy(2:3))
            c = [p%big_l*ev(1), -p%big_b + p%big_l*ev(2), p%big_l*ev(3)]
            b = body_axes(p, n)
            x = rg%b_prime*mass_centre(p, c, n) + QPT(1)*b(1, :) + QPT(2)*b(2, :) + &
                QPT(3)*b(3, :)
        end function absolute
    end subroutine test_pose

    !> The derivatives of the point's two coordinates (record_model_sens with point:
    !! forward sensitivities plus the position's own change with the rig) along I1, I2,
    !! cg_depth, tilt, sway, l, b_prime and the amplitude against central differences of
    !! whole runs, extrapolated (error h^4), at 41 samples over 8 s: within 1e-5 of the
    !! largest excursion for a change of each quantity by its size.
    subroutine test_sens(t)
        type(tester_t), intent(inout) :: t
        integer, parameter :: NT = 41, NQ = 8
        character(len=16), parameter :: NAMES(NQ) = [character(len=16) :: 'I1', 'I2', &
            'cg_depth', 'tilt', 'sway', 'l', 'b_prime', 'amplitude']
        type(rig_t) :: rg
        type(start_t) :: st
        type(accuracy_t) :: acc
        real(dp) :: ts(NT), xs(NQ)
        integer :: i
        call turned_rig(rg, st, acc)
        acc%rtol = 1.0e-11_dp
        acc%atol = 1.0e-13_dp
        do i = 1, NT
            ts(i) = 0.2_dp*(i - 1)
        end do
        xs = [rg%inertia(1:2), input_value(rg, st, 'cg_depth'), st%tilt, st%sway, rg%l, &
              rg%b_prime, st%amplitude]
        call check_sens(t, 'point', 'excursion', rg, st, acc, ts, NAMES, xs, point=QPT)
    end subroutine test_sens

    !> A video track seen from below (60 frames a second, 20 s; 0.5 mm a pixel, the camera's
    !! origin at (640, 360) px, noise 0.3 px) of a point 5 cm off the axis (record_point =
    !! 0, 0.05, 0) of a symmetric rig released from 20 degrees with a sway (l sway) of 10 %
    !! of the point's excursion in the torsion (0.05 m sin 20 degrees), a sway that grows
    !! from the torsion's energy to several cm by the record's end, fitted from I1 2 % off,
    !! no sway and a scale 1 % off for I1, sway, the two offsets and the scale: I1 within
    !! 0.05 %, the scale's truth within its 95 % interval.  The same track as a file (t,
    !! x, y in px) through the program: exit 0, I1 within 0.05 % and within its U; in
    !! frame numbers with record_frame_rate and the columns by name: the same I1; a track
    !! of one coordinate, and record_columns naming one, refused with one line naming
    !! record_columns.  The same track the old way: the point's angle about the axis
    !! (origin and scale known; atan2 unwrapped) while the point stays on its circle, as
    !! theta4 of one axis fitted for I1, the amplitude, t0 and the offset: it converges,
    !! and its I1 error (the sway's bias) is larger than the point fit's; both printed.
    subroutine test_goal(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        integer, parameter :: N = 1201
        real(dp), parameter :: SCALE = TRACK_SCALE, ORIGIN(2) = TRACK_ORIGIN
        real(dp), parameter :: QV(3) = [0.0_dp, 0.05_dp, 0.0_dp]
        real(dp), parameter :: AMP = 20.0_dp
        type(deck_t) :: d
        type(rig_t) :: rg
        type(start_t) :: st
        type(accuracy_t) :: acc
        type(record_t) :: rec, ang
        type(identify_result_t) :: res, old
        type(status_t) :: stat
        type(pendulum_t) :: p
        real(dp) :: u(2), w(2), e_new, e_old, sc
        integer :: i, k, ex, m
        real(dp) :: i1_time, i1_frames, u_i1
        character(len=:), allocatable :: goal
        call fresh_dir(DIR)
        call video_rig(rg, st, acc)
        ! the body's sway (l sway) 10 % of the point's excursion in the torsion
        st%sway = 0.1_dp*QV(2)*sin(AMP*deg)/rg%l
        call make_track(rg, st, acc, [((i - 1)/60.0_dp, i=1, N)], 0.0_dp, QV, 13, 0, rec, stat)
        call t%check('point: the video track made'//msg_of(stat), stat%code == 0)
        if (stat%code /= 0) return
        goal = rig_deck('video', '1.20', 'inertia = 0.0522, 0.0630, 0.0304, r = 0.20, '// &
                        'lambda = 0.0, sway_depth = 0.30')//'&start mode = ''raised'', '// &
            'amplitude = 20.0 /'//new_line('a')//'&measurement record = ''goal.dat'', '// &
            'quantity = ''point'', record_point = 0, 0.05, 0, record_scale = 5.05e-4, '// &
            'estimate = ''I1 sway bias scale'' /'//new_line('a')
        call write_text(DIR//'/goal.nml', goal)
        call read_deck(DIR//'/goal.nml', d, stat)
        call t%check('point: the goal deck'//msg_of(stat), stat%code == 0)
        if (stat%code /= 0) return
        call identify_record(d, rec, res, stat)
        call t%check('point: the video track''s fit'//msg_of(stat), stat%code == 0)
        if (stat%code /= 0) return
        call t%check('point: five parameters estimated', res%np == 5)
        e_new = res%i1/rg%inertia(1) - 1.0_dp
        call t%check_close('point: I1 from the track within 0.05 %', res%i1, rg%inertia(1), &
                           5.0e-4_dp, 0.0_dp)
        k = findloc(res%names(1:res%np), 'scale', 1)
        call t%check('point: the scale estimated', k > 0)
        if (k > 0) then
            sc = res%p(k)
            print '(a,3es14.6)', '   scale estimate, truth, u (m/px): ', sc, SCALE, res%u_p(k)
            call t%check('point: the scale''s truth within its 95 % interval', &
                         abs(sc - SCALE) <= max(res%k, 1.96_dp)*res%u_p(k))
        end if
        k = findloc(res%names(1:res%np), 'sway', 1)
        if (k > 0) print '(a,3es14.6)', '   sway estimate, truth, u (rad): ', res%p(k), &
            st%sway, res%u_p(k)
        ! the same track through the program: a file of t, x, y (px) that the deck names
        call write_track(DIR//'/goal.dat', rec, 't (s), x (px), y (px)', .false., .true., 1.0_dp)
        ex = run_cmd(exe//' '//DIR//'/goal.nml --out '//DIR//'/out', DIR)
        call t%check('point: the track''s file through the program: exit 0', ex == 0)
        i1_time = -1.0_dp
        if (ex == 0) then
            i1_time = kv_real(DIR//'/out/goal.identify', 'I1')
            u_i1 = kv_real(DIR//'/out/goal.identify', 'U_I1')
            print '(a,3es14.6)', '   program, track file: I1, truth, U_I1 (kg m^2): ', &
                i1_time, rg%inertia(1), u_i1
            call t%check_close('point: the program''s I1 from the track''s file within '// &
                               '0.05 %', i1_time, rg%inertia(1), 5.0e-4_dp, 0.0_dp)
            call t%check('point: the program''s I1 within its U', &
                         abs(i1_time - rg%inertia(1)) <= u_i1)
        end if
        ! frame numbers (record_frame_rate), the columns by their names: the same I1
        call write_track(DIR//'/frames.dat', rec, 'frame, x (px), y (px)', .true., .true., 1.0_dp)
        call write_text(DIR//'/frames.nml', goal(1:index(goal, 'goal.dat') - 1)// &
            'frames.dat'', record_frame_rate = 60, record_columns = ''frame'', '// &
            '''x (px)'', ''y (px)'''//goal(index(goal, 'goal.dat') + 9:))
        ex = run_cmd(exe//' '//DIR//'/frames.nml --out '//DIR//'/out', DIR)
        call t%check('point: a track in frame numbers through the program: exit 0', ex == 0)
        if (ex == 0) then
            i1_frames = kv_real(DIR//'/out/frames.identify', 'I1')
            call t%check_close('point: a track in frame numbers gives the same I1', &
                               i1_frames, i1_time, 1.0e-6_dp, 0.0_dp)
        end if
        ! a track of one coordinate, and record_columns naming one: refused with one line
        call write_track(DIR//'/one.dat', rec, 't (s), x (px)', .false., .false., 1.0_dp)
        call write_text(DIR//'/one.nml', goal(1:index(goal, 'goal.dat') - 1)//'one.dat'// &
                        goal(index(goal, 'goal.dat') + 8:))
        call write_text(DIR//'/onecol.nml', goal(1:index(goal, 'goal.dat') - 1)// &
            'goal.dat'', record_columns = 1, 2'//goal(index(goal, 'goal.dat') + 9:))
        call refused('one', 'record_columns')
        call refused('onecol', 'record_columns')
        ! a track in mm (its columns' names say so), record_scale left out: the same I1; in
        ! mm with record_scale, and x in mm with y in px: refused with one line
        call write_track(DIR//'/mm.dat', rec, 't (s), x (mm), y (mm)', .false., .true., &
                         1.0e3_dp*SCALE)
        call write_text(DIR//'/mm.nml', replaced(replaced(goal, 'goal.dat', 'mm.dat'), &
                                                 ' record_scale = 5.05e-4,', ''))
        ex = run_cmd(exe//' '//DIR//'/mm.nml --out '//DIR//'/out', DIR)
        call t%check('point: a track in mm through the program: exit 0', ex == 0)
        if (ex == 0) then
            call t%check_close('point: a track in mm gives the same I1', &
                               kv_real(DIR//'/out/mm.identify', 'I1'), &
                               i1_time, 1.0e-5_dp, 0.0_dp)
        end if
        call write_text(DIR//'/mmscale.nml', replaced(goal, 'goal.dat', 'mm.dat'))
        call refused('mmscale', 'record_scale')
        call write_track(DIR//'/mixed.dat', rec, 't (s), x (mm), y (px)', .false., .true., 1.0_dp)
        call write_text(DIR//'/mixed.nml', replaced(goal, 'goal.dat', 'mixed.dat'))
        call refused('mixed', 'different units')
        ! the old way: the point's angle about the axis, as theta4 of one axis
        call make_pendulum(rg, p, stat)
        u = point_position(p, rg%b_prime, QV, VIEW_BELOW, spread(0.0_dp, 1, NSTATE)) - &
            point_position(p, rg%b_prime, [0.0_dp, 0.0_dp, 0.0_dp], VIEW_BELOW, &
                           spread(0.0_dp, 1, NSTATE))
        ! the angle of the point about the axis (atan2, unwrapped: continuous through
        ! +-pi) as long as the point stays on its circle (its distance from the axis within
        ! 10 % of |u|); beyond, the body's sway carries the point around the axis and its
        ! angle there is no torsion (this rig's sway grows from the torsion's energy)
        m = N
        do i = 1, N
            w = u + [rec%vs(i) - ORIGIN(1), rec%vs(N + i) - ORIGIN(2)]*SCALE
            if (abs(norm2(w) - norm2(u)) > 0.1_dp*norm2(u)) then
                m = i - 1
                exit
            end if
        end do
        allocate (ang%t(m), ang%v(m), ang%u(m))
        ang%t = rec%t(1:m)
        do i = 1, m
            w = u + [rec%vs(i) - ORIGIN(1), rec%vs(N + i) - ORIGIN(2)]*SCALE
            ang%v(i) = atan2(u(1)*w(2) - u(2)*w(1), dot_product(u, w))
            if (i > 1) ang%v(i) = ang%v(i) - 2.0_dp*pi*anint((ang%v(i) - ang%v(i - 1))/ &
                                                             (2.0_dp*pi))
        end do
        if (ang%v(1) < 0.0_dp) ang%v = -ang%v
        ang%u = 1.0_dp
        print '(a,f7.2,a,f7.2,a)', '   one-axis angle record: the first ', ang%t(m), &
            ' s of ', rec%t(N), ' s (the point on its circle)'
        call write_text(DIR//'/old.nml', rig_deck('video, old way', '1.20', 'inertia = '// &
            '0.0522, 0.0630, 0.0304, r = 0.20, lambda = 0.0, sway_depth = 0.30')// &
            '&start mode = ''raised'', '// &
            'amplitude = 20.0 /'//new_line('a')//'&measurement record = ''old.dat'', '// &
            'quantity = ''angle'', estimate = ''I1 amplitude t0 bias'' /'//new_line('a'))
        call read_deck(DIR//'/old.nml', d, stat)
        call t%check('point: the old way''s deck'//msg_of(stat), stat%code == 0)
        if (stat%code /= 0) return
        call identify_record(d, ang, old, stat)
        call t%check('point: the one-axis angle fit (old way) converges'//msg_of(stat), &
                     stat%code == 0)
        if (stat%code /= 0) return
        e_old = old%i1/rg%inertia(1) - 1.0_dp
        print '(a,es11.3,a,es11.3,a,es11.3,a)', '   I1 relative error: point fit ', e_new, &
            ', one-axis angle fit (old way) ', e_old, ' (its U_I1/I1 ', old%u_i1_expanded/old%i1, ')'
        call t%check('point: the point''s fit is closer than the old way''s', &
                     abs(e_new) < abs(e_old))
    contains
        !> The deck DIR/name.nml refused: exit 2, one line saying word, no output.
        subroutine refused(name, word)
            character(len=*), intent(in) :: name, word
            integer :: e
            call fresh_dir(DIR//'/out_'//name)
            e = run_cmd(exe//' '//DIR//'/'//name//'.nml --out '//DIR//'/out_'//name, DIR)
            call t%check('point: '//name//': refused (exit 2)', e == 2)
            call t%check('point: '//name//': the line says '//word, &
                         file_has(DIR//'/stderr', word))
            call t%check('point: '//name//': one line', count_lines(DIR//'/stderr') == 1)
            call t%check('point: '//name//': no output', &
                         .not. exists(DIR//'/out_'//name//'/'//name//'.identify'))
        end subroutine refused
    end subroutine test_goal

    !> A 3-axis gyro record (100 Hz, 20 s, noise 0.003 rad/s, a bias on each axis) of the
    !! laboratory rig (principal axes along the hang's), each axis read with its own scale, 1.02, 0.99 and 1.0 (the record's
    !! value the rate over the scale), fitted from I1 2 % off and scales 1 for I1, the
    !! three biases and the three scales (estimate = 'I1 bias scale'): each scale's truth
    !! within its 95 % interval, I1 within 0.1 %.
    subroutine test_rates_scale(t)
        type(tester_t), intent(inout) :: t
        integer, parameter :: N = 2001
        real(dp), parameter :: SIGMA = 0.003_dp, BIAS(3) = [0.004_dp, -0.006_dp, 0.003_dp]
        real(dp), parameter :: SCALES(3) = [1.02_dp, 0.99_dp, 1.0_dp]
        character(len=*), parameter :: NAMES(3) = ['scale_x', 'scale_y', 'scale_z']
        type(rig_t) :: rg
        type(start_t) :: st
        type(accuracy_t) :: acc
        type(deck_t) :: d
        type(record_t) :: rec
        type(identify_result_t) :: res
        type(status_t) :: stat
        real(dp) :: axes(3, 3)
        integer :: i, k, j
        logical :: ok
        call fresh_dir(DIR//'/scales')
        call lab_rig(rg, st, acc)
        call parse_axes('aligned', axes, ok)
        call make_gyro(rg, st, acc, [(0.01_dp*(i - 1), i=1, N)], 0.0_dp, axes, BIAS, SCALES, &
                       SIGMA, 17, 0, rec, stat)
        call t%check('point: the scaled rates made'//msg_of(stat), stat%code == 0)
        if (stat%code /= 0) return
        call write_text(DIR//'/scales/scales.nml', rig_deck('3-axis gyro, scales', '1.18', &
            'inertia = 0.0522, 0.0630, 0.0304, r = 0.25, lambda = 0.64, sway_depth = 0.30')// &
            '&start mode = ''raised'', amplitude = 30.0, tilt = '//sci(st%tilt, 12)//', '// &
            'sway = '//sci(st%sway, 12)//' /'//new_line('a')// &
            '&measurement record = ''scales.dat'', quantity = ''rates'', '// &
            'estimate = ''I1 bias scale'' /'//new_line('a'))
        call read_deck(DIR//'/scales/scales.nml', d, stat)
        call t%check('point: the scales'' deck'//msg_of(stat), stat%code == 0)
        if (stat%code /= 0) return
        call identify_record(d, rec, res, stat)
        call t%check('point: the scales'' fit'//msg_of(stat), stat%code == 0)
        if (stat%code /= 0) return
        call t%check('point: seven parameters estimated (I1, three biases, three scales)', &
                     res%np == 7)
        do j = 1, 3
            k = findloc(res%names(1:res%np), NAMES(j), 1)
            ! (the first axis's scale is the parameter 'scale')
            if (j == 1 .and. k == 0) k = findloc(res%names(1:res%np), 'scale', 1)
            call t%check('point: '//NAMES(j)//' estimated', k > 0)
            if (k == 0) cycle
            print '(a,3es14.6)', '   '//NAMES(j)//' estimate, truth, u: ', res%p(k), &
                SCALES(j), res%u_p(k)
            call t%check('point: '//NAMES(j)//'''s truth within its 95 % interval', &
                         abs(res%p(k) - SCALES(j)) <= max(res%k, 1.96_dp)*res%u_p(k))
        end do
        print '(a,es11.3)', '   I1 relative error with three scales: ', &
            res%i1/rg%inertia(1) - 1.0_dp
        call t%check_close('point: I1 with three scales within 0.1 %', res%i1, &
                           rg%inertia(1), 1.0e-3_dp, 0.0_dp)
    end subroutine test_rates_scale

    !> Misuses of the keys through the program, each exit 2 with one line naming the key
    !! and no output: quantity 'point' without record_point, record_scale <= 0, record_view
    !! not a view, and scale with amplitude on a record of one angle.
    subroutine test_refusal(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        integer, parameter :: NC = 4
        character(len=80), parameter :: KEYS(NC) = [character(len=80) :: &
            'quantity = ''point''', &
            'quantity = ''point'', record_point = 0, 0.05, 0, record_scale = -1e-3', &
            'quantity = ''point'', record_point = 0, 0.05, 0, record_view = ''above''', &
            'quantity = ''angle'', estimate = ''I1 scale amplitude''']
        character(len=24), parameter :: NAMED(NC) = [character(len=24) :: 'record_point', &
            'record_scale', 'record_view', 'scale and amplitude']
        character(len=:), allocatable :: text
        character(len=64) :: line
        integer :: i, ex, nl
        call fresh_dir(DIR//'/refuse')
        text = '# t x y'//new_line('a')
        do i = 1, 200
            write (line, '(f8.3,2f10.3)') 0.01_dp*(i - 1), 640.0_dp + 30.0_dp*sin(0.05_dp*i), &
                360.0_dp + 2.0_dp*cos(0.05_dp*i)
            text = text//trim(line)//new_line('a')
        end do
        call write_text(DIR//'/refuse/track.dat', text)
        do i = 1, NC
            call write_text(DIR//'/refuse/bad.nml', rig_deck('misuse', '1.20', 'inertia = '// &
                '0.0512, 0.0630, 0.0304', .false.)//'&start mode = '// &
                '''raised'', amplitude = 20.0 /'//new_line('a')//'&measurement record = '// &
                '''track.dat'', '//trim(KEYS(i))//' /'//new_line('a'))
            call fresh_dir(DIR//'/refuse/out')
            ex = run_cmd(exe//' '//DIR//'/refuse/bad.nml --out '//DIR//'/refuse/out', &
                         DIR//'/refuse')
            call t%check('point: '//trim(NAMED(i))//' misuse: exit 2', ex == 2)
            call t%check('point: '//trim(NAMED(i))//' misuse: the line names it', &
                         file_has(DIR//'/refuse/stderr', trim(NAMED(i))))
            nl = count_lines(DIR//'/refuse/stderr')
            call t%check('point: '//trim(NAMED(i))//' misuse: one line', nl == 1)
            call t%check('point: '//trim(NAMED(i))//' misuse: no output', &
                         .not. exists(DIR//'/refuse/out/bad.identify'))
        end do
    end subroutine test_refusal

    !> The video track of test_goal's release (the point 5 cm off the axis, a sway of 10 %
    !! of its excursion, 60 frames a second, 0.5 mm a pixel, noise 0.3 px) seen from the
    !! side (record_view = 'side': along n1, the point's n2 component in x, its height in
    !! y), its first 12 s, as a tracker's file through the program, fitted from I1 2 % off
    !! and a scale 1 % off for I1, sway, the two offsets and the scale: exit 0, the output
    !! names the view, I1 within 0.05 % and within its U, the scale's truth within its
    !! interval (k u).  (Beyond 12 s the body's tilt, which grows from the torsion's energy
    !! on this rig, moves the point's height by up to 5 cm, and from these start values the
    !! fit of the 20 s track does not converge.)
    subroutine test_side(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        integer, parameter :: N = 721
        real(dp), parameter :: QV(3) = [0.0_dp, 0.05_dp, 0.0_dp]
        character(len=*), parameter :: D = DIR//'/side'
        type(rig_t) :: rg
        type(start_t) :: st
        type(accuracy_t) :: acc
        type(record_t) :: rec
        type(status_t) :: stat
        real(dp) :: i1, u, sc, usc
        integer :: i, ex
        call fresh_dir(D)
        call video_rig(rg, st, acc)
        st%sway = 0.1_dp*QV(2)*sin(st%amplitude*deg)/rg%l
        call make_track(rg, st, acc, [((i - 1)/60.0_dp, i=1, N)], 0.0_dp, QV, 29, 0, rec, stat, &
                        view=VIEW_SIDE)
        call t%check('point: side: the track made'//msg_of(stat), stat%code == 0)
        if (stat%code /= 0) return
        call t%check('point: side: the torsion shows in x (more than 20 px)', &
                     maxval(rec%vs(1:N)) - minval(rec%vs(1:N)) > 20.0_dp)
        call write_track(D//'/side.dat', rec, 't (s), x (px), y (px)', .false., .true., 1.0_dp)
        call write_text(D//'/side.nml', rig_deck('video, side', '1.20', 'inertia = 0.0522, '// &
            '0.0630, 0.0304, r = 0.20, lambda = 0.0, sway_depth = 0.30')// &
            '&start mode = ''raised'', amplitude = 20.0 /'//new_line('a')// &
            '&measurement record = ''side.dat'', quantity = ''point'', record_point = 0, '// &
            '0.05, 0, record_view = ''side'', record_scale = 5.05e-4, '// &
            'estimate = ''I1 sway bias scale'' /'//new_line('a'))
        ex = run_cmd(exe//' '//D//'/side.nml --out '//D//'/out', D)
        call t%check('point: side: the track''s file through the program: exit 0', ex == 0)
        if (ex /= 0) return
        call t%check('point: side: the output names the view', &
                     file_has(D//'/out/side.identify', 'record_view = side'))
        i1 = kv_real(D//'/out/side.identify', 'I1')
        u = kv_real(D//'/out/side.identify', 'U_I1')
        print '(a,3es14.6)', '   side view, track file: I1, truth, U_I1 (kg m^2): ', i1, &
            rg%inertia(1), u
        call t%check_close('point: side: I1 within 0.05 %', i1, rg%inertia(1), 5.0e-4_dp, 0.0_dp)
        call t%check('point: side: I1 within its U', abs(i1 - rg%inertia(1)) <= u)
        sc = kv_real(D//'/out/side.identify', 'scale')
        usc = kv_real(D//'/out/side.identify', 'u_scale')
        print '(a,3es14.6)', '   side view: scale estimate, truth, u (m/px): ', sc, &
            TRACK_SCALE, usc
        call t%check('point: side: the scale''s truth within its interval', &
                     abs(sc - TRACK_SCALE) <= max(kv_real(D//'/out/side.identify', 'k'), &
                                                  1.96_dp)*usc)
    end subroutine test_side

end module test_point
