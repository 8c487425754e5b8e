!> Tests of records of several releases (&measurement record_split = .true.): records of
!! the program's model (as make_record makes them: the model plus seeded noise, written
!! with 6 decimals of time and 10 digits of value), each held still before its release,
!! joined end to end, one release turned the other way.  The record cut at its holds gives
!! one segment per release, each holding its release; the pooled I1 equals that of a table
!! of releases of the same segments (each fitted alone), and covers the truth; a record
!! of one release gives the same I1 and U as without record_split; a segment too short to
!! fit is refused naming its time span, or skipped with a warning naming it.  Video tracks
!! (quantity 'point') of three releases joined in one file: cut and pooled as the table of
!! their segments, which pools each segment's own fit.
module test_split
    use kinds, only: dp, deg
    use status, only: status_t
    use testing, only: tester_t, msg_of, write_text, run_cmd => run, fresh_dir, file_has, &
        read_kv_text, kv_real, replaced, rig_deck
    use testing_records, only: lab_rig, video_rig, make_track, write_track
    use rig, only: rig_t, start_t, accuracy_t
    use record_fit, only: record_model
    use records, only: record_t
    use record_split, only: release_spans, segment_of
    use work_estimate, only: record_swing_period
    use random, only: rng_t, rng_stream, rng_normal
    implicit none
    private

    public :: run_split_tests

    character(len=*), parameter :: DIR = 'build/test_split'
    real(dp), parameter :: DT = 0.02_dp         !! 50 Hz
    real(dp), parameter :: HOLD = 3.0_dp        !! s held before each release
    real(dp), parameter :: SIGMA = 1.0e-3_dp    !! rad

contains

    subroutine run_split_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        if (t%want('split: a record of three releases cut and pooled as a table')) &
            call test_three(t, exe)
        if (t%want('split: a record of one release gives the fit without record_split')) &
            call test_one(t, exe)
        if (t%want('split: a segment too short to fit: refused or skipped, named')) &
            call test_short(t, exe)
        if (t%want('split: video tracks of three releases: a table, and one track cut')) &
            call test_tracks(t, exe)
    end subroutine run_split_tests

    !> The deck (record FILE; extra: more &measurement settings).
    function deck_text(file, extra) result(s)
        character(len=*), intent(in) :: file, extra
        character(len=:), allocatable :: s
        s = rig_deck('several releases', '1.18', 'inertia = 0.049, 0.0630, 0.0304, '// &
                     'r = 0.25, lambda = 0.64, sway_depth = 0.30')// &
            '&start mode = ''raised'', amplitude = 20.0 /'//new_line('a')// &
            '&measurement record = '''//file//''', quantity = ''angle'', '// &
            'estimate = ''I1 amplitude t0'''//extra//' /'//new_line('a')
    end function deck_text

    !> A record of releases from the amplitudes amps (degrees; negative: turned the other
    !! way), each held HOLD s and swinging swing(j) s, joined end to end: its lines (as the
    !! file holds them), its times and values as read back, the release times.
    subroutine joined(amps, swing, lines, rec, t_rel, stat)
        real(dp), intent(in) :: amps(:), swing(:)
        character(len=40), allocatable, intent(out) :: lines(:)
        type(record_t), intent(out) :: rec
        real(dp), intent(out) :: t_rel(size(amps))
        type(status_t), intent(out) :: stat
        type(rig_t) :: rg
        type(start_t) :: st
        type(accuracy_t) :: acc
        type(rng_t) :: g
        real(dp), allocatable :: tl(:), v(:), tt(:), vv(:)
        real(dp) :: off
        integer :: j, i, n
        call lab_rig(rg, st, acc)
        st%tilt = 0.0_dp
        st%sway = 0.0_dp
        g = rng_stream(5, 0)
        allocate (tt(0), vv(0))
        off = 0.0_dp
        do j = 1, size(amps)
            n = nint((HOLD + swing(j))/DT)
            tl = [(DT*i, i=0, n - 1)]
            allocate (v(n))
            st%amplitude = amps(j)
            call record_model(rg, st, acc, tl, HOLD, .false., v, stat)
            if (stat%code /= 0) return
            t_rel(j) = off + HOLD
            tt = [tt, off + tl]
            vv = [vv, v]
            deallocate (v)
            off = off + n*DT
        end do
        n = size(tt)
        allocate (lines(n), rec%t(n), rec%v(n), rec%u(n))
        do i = 1, n
            write (lines(i), '(f12.6,es19.9e3)') tt(i), vv(i) + SIGMA*rng_normal(g)
            read (lines(i), *) rec%t(i), rec%v(i)
        end do
        rec%u = 1.0_dp
    end subroutine joined

    !> Lines lo .. hi of a record written to path, with a header.
    subroutine write_lines(path, lines, lo, hi)
        character(len=*), intent(in) :: path
        character(len=40), intent(in) :: lines(:)
        integer, intent(in) :: lo, hi
        character(len=:), allocatable :: text
        integer :: i
        text = '# t (s)  theta4 (rad)'//new_line('a')
        do i = lo, hi
            text = text//trim(lines(i))//new_line('a')
        end do
        call write_text(path, text)
    end subroutine write_lines

    !> The checks of a cut of three releases (released at t_rel, each held HOLD s before):
    !! three segments and three holds, each segment from 1.5 s or more before its release to
    !! more than 8 s after it, and ending before the next release's hold; .false. when the
    !! cut has not three segments.  label: the checks' prefix.
    logical function three_spans(t, label, rec, t_rel, lo, hi, nh) result(three)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: label
        type(record_t), intent(in) :: rec
        real(dp), intent(in) :: t_rel(3)
        integer, intent(in) :: lo(:), hi(:), nh
        logical :: ok
        integer :: j
        three = size(lo) == 3
        call t%check(label//'three segments and three holds', three .and. nh == 3)
        if (.not. three) return
        ok = .true.
        do j = 1, 3
            ok = ok .and. rec%t(lo(j)) <= t_rel(j) - 1.5_dp .and. rec%t(hi(j)) > t_rel(j) + 8.0_dp
        end do
        do j = 1, 2
            ok = ok .and. rec%t(hi(j)) < t_rel(j + 1) - HOLD
        end do
        call t%check(label//'each segment holds its release and no other', ok)
    end function three_spans

    !> Three releases (20, -15 and 25 degrees), each held 3 s and swinging 12 s: three
    !! segments, each holding its release and none another's; the pooled I1 of the record
    !! equals that of the table of its three segments (each fitted alone) and covers the
    !! truth; the output lists each segment's span and I1.
    subroutine test_three(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=40), allocatable :: lines(:)
        type(record_t) :: rec
        type(status_t) :: stat
        real(dp) :: t_rel(3), i1, u, i1t, ut, tp
        integer, allocatable :: lo(:), hi(:)
        integer :: nh, j, ex
        character(len=:), allocatable :: out, table
        character(len=256) :: val
        call fresh_dir(DIR//'/three')
        call joined([20.0_dp, -15.0_dp, 25.0_dp], [12.0_dp, 12.0_dp, 12.0_dp], lines, rec, &
                    t_rel, stat)
        call t%check('split: the joined record made'//msg_of(stat), stat%code == 0)
        if (stat%code /= 0) return
        call write_lines(DIR//'/three/joined.dat', lines, 1, size(lines))
        ! the cut, with the period identify takes
        tp = record_swing_period(rec)
        call release_spans(rec, tp, lo, hi, nh)
        if (.not. three_spans(t, 'split: ', rec, t_rel, lo, hi, nh)) return
        ! the table of the same segments, each a release of its own
        table = 'trial,record'//new_line('a')
        do j = 1, 3
            call write_lines(DIR//'/three/seg'//achar(48 + j)//'.dat', lines, lo(j), hi(j))
            table = table//'s'//achar(48 + j)//',seg'//achar(48 + j)//'.dat'//new_line('a')
        end do
        call write_text(DIR//'/three/segs.csv', table)
        call write_text(DIR//'/three/split.nml', deck_text('joined.dat', &
                        ', record_split = .true.'))
        out = DIR//'/three/out'
        ex = run_cmd(exe//' '//DIR//'/three/split.nml --out '//out, DIR//'/three')
        call t%check('split: the record of three releases fitted (exit 0)', ex == 0)
        if (ex /= 0) return
        call write_text(DIR//'/three/table.nml', replaced(deck_text('x', ''), &
                        'record = ''x''', 'trials = ''segs.csv'''))
        ex = run_cmd(exe//' '//DIR//'/three/table.nml --out '//out//'t', DIR//'/three')
        call t%check('split: the table of its segments fitted (exit 0)', ex == 0)
        if (ex /= 0) return
        i1 = kv_real(out//'/split.identify', 'I1')
        u = kv_real(out//'/split.identify', 'U_I1')
        i1t = kv_real(out//'t/table.identify', 'I1')
        ut = kv_real(out//'t/table.identify', 'U_I1')
        print '(a,4es15.7)', '   split I1, U; table I1, U: ', i1, u, i1t, ut
        call t%check('split: three releases pooled', &
                     kv_real(out//'/split.identify', 'n_trials') == 3.0_dp)
        call t%check_close('split: the pooled I1 is the table''s', i1, i1t, 1.0e-12_dp, 0.0_dp)
        call t%check_close('split: its U is the table''s', u, ut, 1.0e-9_dp, 0.0_dp)
        call t%check('split: the pooled I1 covers the truth', abs(i1 - 0.0512_dp) <= u .and. u > 0.0_dp)
        do j = 1, 3
            call t%check_close('split: segment '//achar(48 + j)//'''s I1 is its own fit''s', &
                               kv_real(out//'/split.identify', 'I1_trial('//achar(48 + j)//')'), &
                               kv_real(out//'t/table.identify', 'I1_trial('//achar(48 + j)//')'), &
                               1.0e-12_dp, 0.0_dp)
            call read_kv_text(out//'/split.identify', 'trial('//achar(48 + j)//')', val)
            call t%check('split: segment '//achar(48 + j)//' named with its span', &
                         index(val, 'segment '//achar(48 + j)//', t = ') == 1 .and. &
                         index(val, ' s to ') > 0)
        end do
    end subroutine test_three

    !> A record of one release (held, then 12 s): I1 and U with record_split as without.
    subroutine test_one(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=40), allocatable :: lines(:)
        type(record_t) :: rec
        type(status_t) :: stat
        real(dp) :: t_rel(1)
        character(len=256) :: a, b, ua, ub
        integer :: ex1, ex2
        call fresh_dir(DIR//'/one')
        call joined([20.0_dp], [12.0_dp], lines, rec, t_rel, stat)
        call t%check('split: the one-release record made'//msg_of(stat), stat%code == 0)
        if (stat%code /= 0) return
        call write_lines(DIR//'/one/one.dat', lines, 1, size(lines))
        call write_text(DIR//'/one/plain.nml', deck_text('one.dat', ''))
        call write_text(DIR//'/one/cut.nml', deck_text('one.dat', ', record_split = .true.'))
        ex1 = run_cmd(exe//' '//DIR//'/one/plain.nml --out '//DIR//'/one/out', DIR//'/one')
        ex2 = run_cmd(exe//' '//DIR//'/one/cut.nml --out '//DIR//'/one/out', DIR//'/one')
        call t%check('split: one release, both fitted (exit 0)', ex1 == 0 .and. ex2 == 0)
        call read_kv_text(DIR//'/one/out/plain.identify', 'I1', a)
        call read_kv_text(DIR//'/one/out/cut.identify', 'I1', b)
        call read_kv_text(DIR//'/one/out/plain.identify', 'U_I1', ua)
        call read_kv_text(DIR//'/one/out/cut.identify', 'U_I1', ub)
        call t%check('split: one release, the same I1 and U to the last digit', &
                     len_trim(a) > 0 .and. a == b .and. ua == ub)
        call t%check('split: one release, one trial', &
                     kv_real(DIR//'/one/out/cut.identify', 'n_trials') == 1.0_dp)
    end subroutine test_one

    !> Two releases and a third that swings 1.5 s (about one period): refused (exit 2, one
    !! line naming the segment's span), or with on_failure = 'skip' left out (exit 0, two
    !! releases pooled, a warning naming its span).
    subroutine test_short(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=40), allocatable :: lines(:)
        type(record_t) :: rec
        type(status_t) :: stat
        real(dp) :: t_rel(3)
        integer :: ex
        logical :: ok
        character(len=256) :: val
        call fresh_dir(DIR//'/short')
        call joined([20.0_dp, -15.0_dp, 25.0_dp], [12.0_dp, 12.0_dp, 1.5_dp], lines, rec, &
                    t_rel, stat)
        call t%check('split: the record with a short release made'//msg_of(stat), &
                     stat%code == 0)
        if (stat%code /= 0) return
        call write_lines(DIR//'/short/short.dat', lines, 1, size(lines))
        call write_text(DIR//'/short/stop.nml', deck_text('short.dat', ', record_split = .true.'))
        ex = run_cmd(exe//' '//DIR//'/short/stop.nml --out '//DIR//'/short/out', DIR//'/short')
        call t%check('split: a segment too short: exit 2', ex == 2)
        ok = file_has(DIR//'/short/stderr', 'segment t = ')
        if (ok) ok = file_has(DIR//'/short/stderr', 'too short to fit')
        call t%check('split: a segment too short: the line names its span', ok)
        call t%check('split: a segment too short: no output', &
                     .not. file_has(DIR//'/short/out/stop.identify', 'I1'))
        call write_text(DIR//'/short/skip.nml', deck_text('short.dat', &
                        ', record_split = .true., on_failure = ''skip'''))
        ex = run_cmd(exe//' '//DIR//'/short/skip.nml --out '//DIR//'/short/out', DIR//'/short')
        call t%check('split: a segment too short skipped: exit 0', ex == 0)
        if (ex /= 0) return
        ok = kv_real(DIR//'/short/out/skip.identify', 'n_trials') == 2.0_dp
        if (ok) ok = kv_real(DIR//'/short/out/skip.identify', 'n_trials_skipped') == 1.0_dp
        call t%check('split: two releases pooled, one skipped', ok)
        call read_kv_text(DIR//'/short/out/skip.identify', 'I1', val)
        call t%check('split: the skipped segment named in the output', &
                     file_has(DIR//'/short/out/skip.identify', 'segment 3, t = '))
        call t%check('split: the two releases cover the truth', &
                     abs(kv_real(DIR//'/short/out/skip.identify', 'I1') - 0.0512_dp) <= &
                     kv_real(DIR//'/short/out/skip.identify', 'U_I1'))
    end subroutine test_short

    !> Video tracks (quantity 'point', from below, of a point 5 cm off the axis) of three
    !! releases of the symmetric rig (20, -15 and 25 degrees), each held 3 s and swinging
    !! 12 s, joined end to end in one tracker's file (t, x, y in px): cut at its holds
    !! (record_split), three segments, each holding its release, pooled as the table of
    !! those segments is (the same I1 and U), covering the truth; each segment's I1 in the
    !! table is its own fit's (a deck of its own), and the pooled I1 the weighted mean of
    !! those fits (weights 1/u_I1_trial(j)^2, the releases consistent).
    subroutine test_tracks(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        real(dp), parameter :: AMPS(3) = [20.0_dp, -15.0_dp, 25.0_dp]
        real(dp), parameter :: QV(3) = [0.0_dp, 0.05_dp, 0.0_dp], SWING = 12.0_dp
        character(len=*), parameter :: D = DIR//'/tracks', HEAD = 't (s), x (px), y (px)'
        type(rig_t) :: rg
        type(start_t) :: st
        type(accuracy_t) :: acc
        type(record_t) :: one, rec
        type(status_t) :: stat
        real(dp), allocatable :: tl(:), tt(:), xs(:), ys(:)
        real(dp) :: t_rel(3), off, i1, u, i1s(3), us(3), tp
        integer, allocatable :: lo(:), hi(:)
        integer :: i, j, n, nh, ex
        character(len=:), allocatable :: table
        character :: c
        call fresh_dir(D)
        call video_rig(rg, st, acc)
        n = nint((HOLD + SWING)*60.0_dp)
        tl = [(i/60.0_dp, i=0, n - 1)]
        allocate (tt(0), xs(0), ys(0))
        off = 0.0_dp
        do j = 1, 3
            st%amplitude = AMPS(j)
            call make_track(rg, st, acc, tl, HOLD, QV, 23, j, one, stat)
            call t%check('split: track '//achar(48 + j)//' made'//msg_of(stat), stat%code == 0)
            if (stat%code /= 0) return
            t_rel(j) = off + HOLD
            tt = [tt, off + tl]
            xs = [xs, one%vs(1:n)]
            ys = [ys, one%vs(n + 1:2*n)]
            off = off + n/60.0_dp
        end do
        ! the record as the reader gives it: both coordinates, the value the one with the
        ! larger swing
        rec%t = tt
        rec%vs = [xs, ys]
        rec%v = xs
        if (maxval(ys) - minval(ys) > maxval(xs) - minval(xs)) rec%v = ys
        allocate (rec%u(size(tt)))
        rec%u = 1.0_dp
        call write_track(D//'/joined.dat', rec, HEAD, .false., .true., 1.0_dp)
        tp = record_swing_period(rec)
        call release_spans(rec, tp, lo, hi, nh)
        if (.not. three_spans(t, 'split: tracks: ', rec, t_rel, lo, hi, nh)) return
        table = 'trial,record'//new_line('a')
        do j = 1, 3
            c = achar(48 + j)
            call write_track(D//'/seg'//c//'.dat', segment_of(rec, lo(j), hi(j)), HEAD, &
                             .false., .true., 1.0_dp)
            table = table//'s'//c//',seg'//c//'.dat'//new_line('a')
            call write_text(D//'/seg'//c//'.nml', track_deck('record = ''seg'//c//'.dat'''))
        end do
        call write_text(D//'/segs.csv', table)
        call write_text(D//'/split.nml', track_deck('record = ''joined.dat'', '// &
                                                    'record_split = .true.'))
        call write_text(D//'/table.nml', track_deck('trials = ''segs.csv'''))
        ex = run_cmd(exe//' '//D//'/split.nml --out '//D//'/out', D)
        call t%check('split: tracks: the joined track fitted (exit 0)', ex == 0)
        if (ex /= 0) return
        ex = run_cmd(exe//' '//D//'/table.nml --out '//D//'/out', D)
        call t%check('split: tracks: the table of its segments fitted (exit 0)', ex == 0)
        if (ex /= 0) return
        i1 = kv_real(D//'/out/split.identify', 'I1')
        u = kv_real(D//'/out/split.identify', 'U_I1')
        print '(a,4es15.7)', '   tracks: split I1, U; table I1, U: ', i1, u, &
            kv_real(D//'/out/table.identify', 'I1'), kv_real(D//'/out/table.identify', 'U_I1')
        call t%check('split: tracks: three releases pooled', &
                     kv_real(D//'/out/split.identify', 'n_trials') == 3.0_dp)
        call t%check('split: tracks: the output says quantity point', &
                     file_has(D//'/out/split.identify', 'quantity = point'))
        call t%check_close('split: tracks: the pooled I1 is the table''s', i1, &
                           kv_real(D//'/out/table.identify', 'I1'), 1.0e-12_dp, 0.0_dp)
        call t%check_close('split: tracks: its U is the table''s', u, &
                           kv_real(D//'/out/table.identify', 'U_I1'), 1.0e-9_dp, 0.0_dp)
        call t%check('split: tracks: the pooled I1 covers the truth', &
                     abs(i1 - rg%inertia(1)) <= u .and. u > 0.0_dp)
        ! each segment alone: its I1 the table's, and the weighted mean of them the pool's
        do j = 1, 3
            c = achar(48 + j)
            ex = run_cmd(exe//' '//D//'/seg'//c//'.nml --out '//D//'/out', D)
            call t%check('split: tracks: segment '//c//' alone fitted (exit 0)', ex == 0)
            if (ex /= 0) return
            i1s(j) = kv_real(D//'/out/seg'//c//'.identify', 'I1')
            us(j) = kv_real(D//'/out/table.identify', 'u_I1_trial('//c//')')
            call t%check_close('split: tracks: segment '//c//'''s I1 in the table is its '// &
                               'own fit''s', kv_real(D//'/out/table.identify', 'I1_trial('// &
                               c//')'), i1s(j), 1.0e-12_dp, 0.0_dp)
        end do
        call t%check('split: tracks: the releases consistent', &
                     file_has(D//'/out/table.identify', 'consistency = consistent'))
        call t%check_close('split: tracks: the pooled I1 is the separate fits'' weighted mean', &
                           i1, sum(i1s/us**2)/sum(1.0_dp/us**2), 1.0e-12_dp, 0.0_dp)
    contains
        !> The tracks' deck with the record (or table) what.
        function track_deck(what) result(s)
            character(len=*), intent(in) :: what
            character(len=:), allocatable :: s
            s = rig_deck('tracks', '1.20', 'inertia = 0.0522, 0.0630, 0.0304, r = 0.20, '// &
                         'lambda = 0.0, sway_depth = 0.30')// &
                '&start mode = ''raised'', amplitude = 20.0 /'//new_line('a')// &
                '&measurement '//what//', quantity = ''point'', record_point = 0, 0.05, 0, '// &
                'record_scale = 5.0e-4, estimate = ''I1 amplitude t0 bias'' /'//new_line('a')
        end function track_deck
    end subroutine test_tracks

end module test_split
