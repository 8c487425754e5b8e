!> A small test harness: checks that count, print failures with both values, and a
!! closing line "N passed, N failed"; and the small helpers the test suites share (files and
!! their lines, shell commands, scratch folders, text).
module testing
    use kinds, only: dp
    use status, only: status_t
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use crc64, only: crc64_of, hex16
    use, intrinsic :: iso_c_binding, only: c_int, c_long
    use random, only: rng_t, rng_stream, rng_normal
    use text, only: rshort
    use deck, only: deck_t, read_deck
    use deck_runs, only: rig_of
    use period_inversion, only: torsion_period_s
    implicit none
    private

    public :: write_text, exists, file_has, count_lines, line_starts, first_line, read_kv_text
    public :: run, shell_count, scratch_dir, fresh_dir, empty_dir, abs_path, no_nan
    public :: msg_of, upper, seal_records, message_lines, children_cpu_seconds
    public :: kv_real, replaced, rig_deck
    public :: noisy, true_periods, periods_text, full_text

    type, public :: tester_t
        integer :: passed = 0
        integer :: failed = 0
        integer :: wanted = 0                   !! calls of want that said yes
        character(len=:), allocatable :: only   !! run only the parts whose label contains this
    contains
        procedure :: check
        procedure :: check_close
        procedure :: want
        procedure :: summary
    end type tester_t

    interface
        !> C library getrusage(2); `usage` is struct rusage (18 longs on Linux, room left).
        integer(c_int) function c_getrusage(who, usage) bind(C, name='getrusage')
            import :: c_int, c_long
            integer(c_int), value :: who
            integer(c_long), intent(out) :: usage(*)
        end function c_getrusage
    end interface

contains

    !> CPU seconds (user and system) of every child process this process has waited for,
    !! with their own waited-for children (getrusage RUSAGE_CHILDREN): a command's CPU time
    !! is the difference across its execute_command_line, which the load of the machine
    !! does not inflate as it does the wall time.
    function children_cpu_seconds() result(s)
        real(dp) :: s
        integer(c_int), parameter :: RUSAGE_CHILDREN = -1_c_int
        integer(c_long) :: ru(32)
        ru = 0
        s = 0.0_dp
        if (c_getrusage(RUSAGE_CHILDREN, ru) /= 0) return
        s = real(ru(1) + ru(3), dp) + 1.0e-6_dp*real(ru(2) + ru(4), dp)
    end function children_cpu_seconds

    !> True when the part of a suite labelled `name` is to run (no filter, or the filter is
    !! part of the label); counts the parts that run.
    logical function want(self, name)
        class(tester_t), intent(inout) :: self
        character(len=*), intent(in) :: name
        want = .true.
        if (allocated(self%only)) then
            if (len_trim(self%only) > 0) want = index(name, trim(self%only)) > 0
        end if
        if (want) then
            self%wanted = self%wanted + 1
            write (*, '(a)') '== '//name
        end if
    end function want

    !> Record a pass when cond holds, else a failure with its name.
    subroutine check(self, name, cond)
        class(tester_t), intent(inout) :: self
        character(len=*), intent(in) :: name
        logical, intent(in) :: cond
        if (cond) then
            self%passed = self%passed + 1
        else
            self%failed = self%failed + 1
            write (*, '(a)') 'FAIL: '//name
        end if
    end subroutine check

    !> Pass when |actual - expected| <= atol + rtol*|expected| and both are finite.
    subroutine check_close(self, name, actual, expected, rtol, atol)
        class(tester_t), intent(inout) :: self
        character(len=*), intent(in) :: name
        real(dp), intent(in) :: actual, expected
        real(dp), intent(in), optional :: rtol, atol
        real(dp) :: rt, at
        logical :: ok
        rt = 0.0_dp
        at = 0.0_dp
        if (present(rtol)) rt = rtol
        if (present(atol)) at = atol
        ok = ieee_is_finite(actual) .and. ieee_is_finite(expected)
        if (ok) ok = abs(actual - expected) <= at + rt*abs(expected)
        if (ok) then
            self%passed = self%passed + 1
        else
            self%failed = self%failed + 1
            write (*, '(a,es24.16,a,es24.16,a,es10.2,a,es10.2)') 'FAIL: '//name//': got ', &
                actual, ' expected ', expected, ' rtol ', rt, ' atol ', at
        end if
    end subroutine check_close

    !> Print the closing line; return .true. when nothing failed.
    logical function summary(self)
        class(tester_t), intent(in) :: self
        write (*, '(i0,a,i0,a)') self%passed, ' passed, ', self%failed, ' failed'
        summary = self%failed == 0
    end function summary

    ! ---------------------------------------------------------------------------------------
    ! files and their lines

    !> Write text to path as it is, byte for byte (no line end added), replacing the file.
    subroutine write_text(path, text)
        character(len=*), intent(in) :: path, text
        integer :: u
        open (newunit=u, file=path, status='replace', action='write', access='stream', &
              form='unformatted')
        write (u) text
        close (u)
    end subroutine write_text

    !> Whether a file (or folder) of this path exists.
    logical function exists(path)
        character(len=*), intent(in) :: path
        inquire (file=path, exist=exists)
    end function exists

    !> True when the text file path contains word.
    logical function file_has(path, word)
        character(len=*), intent(in) :: path, word
        integer :: u, ios
        character(len=4096) :: line
        file_has = .false.
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (index(line, word) > 0) then
                file_has = .true.
                exit
            end if
        end do
        close (u)
    end function file_has

    !> Number of lines of a text file (0 when absent); with s, those that contain s (that
    !! start with it when at_start).
    integer function count_lines(path, s, at_start) result(n)
        character(len=*), intent(in) :: path
        character(len=*), intent(in), optional :: s     !! default '': every line
        logical, intent(in), optional :: at_start       !! default .false.
        integer :: u, ios, i
        logical :: start
        character(len=8192) :: line
        start = .false.
        if (present(at_start)) start = at_start
        n = 0
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            i = 1
            if (present(s)) then
                if (len(s) > 0) i = index(line, s)
            end if
            if (i == 1 .or. (i > 1 .and. .not. start)) n = n + 1
        end do
        close (u)
    end function count_lines

    !> Lines of a file of standard error that are messages, not 'bifilar: note: ' lines (the
    !! one line a long run may print at its start saying what it does and how long it will
    !! take).
    integer function message_lines(path) result(n)
        character(len=*), intent(in) :: path
        n = count_lines(path) - count_lines(path, 'bifilar: note: ', .true.)
    end function message_lines

    !> Whether line k of a file starts with s.
    logical function line_starts(path, k, s)
        character(len=*), intent(in) :: path, s
        integer, intent(in) :: k
        integer :: u, ios, i
        character(len=8192) :: line
        line_starts = .false.
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do i = 1, k
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
        end do
        close (u)
        if (ios == 0) line_starts = index(line, s) == 1
    end function line_starts

    !> The first line of a file ('' when none).
    function first_line(path) result(s)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: s
        character(len=4096) :: buf
        integer :: u, ios
        s = ''
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) return
        read (u, '(a)', iostat=ios) buf
        if (ios == 0) s = trim(buf)
        close (u)
    end function first_line

    !> The text after 'key = ' in a key = value file ('' when absent).
    subroutine read_kv_text(path, key, val)
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
    end subroutine read_kv_text

    !> True when no data line (not starting '#') of any file in dir holds nan or inf, and no
    !! line of any file holds '****' (a number too wide for its format).
    logical function no_nan(dir)
        character(len=*), intent(in) :: dir
        integer :: ex
        ! (an effective number of degrees of freedom may be infinite: dof_eff = inf, and
        ! identify's own part's dof_own = inf; a word such as 'inflated' in a warning is no Inf)
        call execute_command_line('cat '//dir//'/* 2>/dev/null | grep -v ''^#'' | '// &
            'grep -vE ''^dof_(eff|own) = inf$'' | grep -qiE ''(^|[^a-z])[+-]?(nan|inf|infinity)'// &
            '([^a-z]|$)''', exitstat=ex)
        no_nan = ex /= 0
        call execute_command_line('cat '//dir//'/* 2>/dev/null | grep -qF ''****''', exitstat=ex)
        no_nan = no_nan .and. ex /= 0
    end function no_nan

    ! ---------------------------------------------------------------------------------------
    ! shell commands and scratch folders

    !> Run a shell command with stdout to d/stdout and stderr to d/stderr; its exit status.
    integer function run(cmd, d) result(ex)
        character(len=*), intent(in) :: cmd, d
        ex = -1
        call execute_command_line('('//cmd//') > '//d//'/stdout 2> '//d//'/stderr', exitstat=ex)
    end function run

    !> The integer printed by a shell command (-1 when none); dir holds the scratch file.
    integer function shell_count(cmd, dir) result(n)
        character(len=*), intent(in) :: cmd, dir
        integer :: u, ios
        n = -1
        call execute_command_line(cmd//' > '//dir//'/count.txt 2>/dev/null')
        open (newunit=u, file=dir//'/count.txt', status='old', action='read', iostat=ios)
        if (ios == 0) read (u, *, iostat=ios) n
        if (ios == 0) close (u, status='delete')
    end function shell_count

    !> The folder path and its parents, made when missing (what is in it stays).
    subroutine scratch_dir(path)
        character(len=*), intent(in) :: path
        call execute_command_line('mkdir -p '//path)
    end subroutine scratch_dir

    !> An empty folder path: removed with all it holds, then made anew.
    subroutine fresh_dir(path)
        character(len=*), intent(in) :: path
        call execute_command_line('rm -rf '//path//' && mkdir -p '//path)
    end subroutine fresh_dir

    !> Whether a folder holds nothing, hidden entries included (also when it is missing).
    logical function empty_dir(dir)
        character(len=*), intent(in) :: dir
        integer :: ex
        ex = -1
        call execute_command_line('test -z "$(ls -A '//dir//' 2>/dev/null)"', exitstat=ex)
        empty_dir = ex == 0
    end function empty_dir

    !> A path as an absolute one (for commands run in another folder).
    function abs_path(path) result(a)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: a
        character(len=4096) :: cwd
        integer :: st
        a = path
        if (path(1:1) == '/') return
        call get_environment_variable('PWD', cwd, status=st)
        if (st == 0) a = trim(cwd)//'/'//path
    end function abs_path

    !> Give every record of the sweep checkpoint at path (the lines between `done K` and
    !! `end` with a blank before their last 16 characters) the checksum of its text again, so
    !! that a value changed on purpose passes the checksum and only the check of the values
    !! themselves can refuse it.
    subroutine seal_records(path)
        character(len=*), intent(in) :: path
        character(len=4096), allocatable :: ls(:)
        character(len=4096) :: line
        integer :: u, ios, n, k, m
        logical :: inside
        allocate (ls(0))
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            ls = [character(len=4096) :: ls, line]
        end do
        close (u)
        n = size(ls)
        inside = .false.
        do k = 1, n
            m = len_trim(ls(k))
            if (index(ls(k), 'done ') == 1) then
                inside = .true.
            else if (ls(k) == 'end') then
                inside = .false.
            else if (inside .and. m > 17) then
                if (ls(k)(m - 16:m - 16) == ' ') ls(k)(m - 15:m) = hex16(crc64_of(ls(k)(1:m - 17)))
            end if
        end do
        open (newunit=u, file=path, status='replace', action='write', iostat=ios)
        if (ios /= 0) return
        do k = 1, n
            write (u, '(a)') trim(ls(k))
        end do
        close (u)
    end subroutine seal_records

    ! ---------------------------------------------------------------------------------------
    ! text

    !> A status's message, '(no message)' when it has none.
    function msg_of(stat) result(m)
        type(status_t), intent(in) :: stat
        character(len=:), allocatable :: m
        m = '(no message)'
        if (allocated(stat%msg)) m = stat%msg
    end function msg_of

    !> s in capitals (ASCII letters).
    pure function upper(s) result(r)
        character(len=*), intent(in) :: s
        character(len=len(s)) :: r
        integer :: i
        r = s
        do i = 1, len(s)
            if (s(i:i) >= 'a' .and. s(i:i) <= 'z') r(i:i) = achar(iachar(s(i:i)) - 32)
        end do
    end function upper

    ! ---------------------------------------------------------------------------------------
    ! decks and outputs of records (suites rates, point, split)

    !> The number after 'key = ' in a key = value file (-huge when absent or no number).
    real(dp) function kv_real(path, key) result(x)
        character(len=*), intent(in) :: path, key
        character(len=256) :: val
        integer :: ios
        call read_kv_text(path, key, val)
        x = -huge(1.0_dp)
        read (val, *, iostat=ios) x
        if (ios /= 0) x = -huge(1.0_dp)
    end function kv_real

    !> text with its first old replaced by new (text itself when old is not in it).
    function replaced(text, old, new) result(r)
        character(len=*), intent(in) :: text, old, new
        character(len=:), allocatable :: r
        integer :: j
        j = index(text, old)
        r = text
        if (j > 0) r = text(1:j - 1)//new//text(j + len(old):)
    end function replaced

    !> The head of an identify deck on the records' laboratory rigs: &scene (title), a
    !! &suspension of b = b' = 0.40 m, l = 1.20 m, l_prime, g = 9.80665, &body mass = 3.10
    !! and then body (the rest of the group, from its inertia: 'inertia = 0.049, ...'), and
    !! unless tight is .false. &integration rtol = 1e-10, atol = 1e-12; each line ended.
    function rig_deck(title, l_prime, body, tight) result(s)
        character(len=*), intent(in) :: title, l_prime, body
        logical, intent(in), optional :: tight
        character(len=:), allocatable :: s
        character(len=*), parameter :: NL = new_line('a')
        s = '&scene title = '''//title//''', analyses = ''identify'' /'//NL// &
            '&suspension b = 0.40, b_prime = 0.40, l = 1.20, l_prime = '//l_prime// &
            ', g = 9.80665 /'//NL//'&body mass = 3.10, '//body//' /'//NL
        if (present(tight)) then
            if (.not. tight) return
        end if
        s = s//'&integration rtol = 1e-10, atol = 1e-12 /'//NL
    end function rig_deck

    ! ---------------------------------------------------------------------------------------
    ! timed periods (suites tare, calibrate)

    !> The periods p timed with normal noise of standard deviation u (s): stream (seed, k)
    !! of module random.
    function noisy(p, u, seed, k) result(q)
        real(dp), intent(in) :: p(:), u
        integer, intent(in) :: seed, k
        real(dp) :: q(size(p))
        type(rng_t) :: g
        integer :: j
        g = rng_stream(seed, k)
        do j = 1, size(p)
            q(j) = p(j) + u*rng_normal(g)
        end do
    end function noisy

    !> The exact torsion periods at amps (degrees) of the laboratory rig (b = b' = 0.40,
    !! l = l' = 1.2, g = 9.80665) with a body of this mass and I1 (I2, I3 = 0.05, 0.04,
    !! cg_depth = 0.02), its deck written as dir/name_truth.nml.
    subroutine true_periods(dir, name, mass, i1, amps, per, ok)
        character(len=*), intent(in) :: dir, name
        real(dp), intent(in) :: mass, i1, amps(:)
        real(dp), intent(out) :: per(size(amps))
        logical, intent(out) :: ok
        type(deck_t) :: d
        type(status_t) :: st
        integer :: j
        per = 0.0_dp
        call write_text(dir//'/'//name//'_truth.nml', '&scene analyses = ''simulate'' /'// &
            new_line('a')//'&suspension b = 0.4, b_prime = 0.4, l = 1.2, l_prime = 1.2, '// &
            'g = 9.80665 /'//new_line('a')//'&body mass = '//rshort(mass)//', inertia = '// &
            rshort(i1)//', 0.05, 0.04, cg_depth = 0.02, cg_offset = 0.0 /'//new_line('a'))
        call read_deck(dir//'/'//name//'_truth.nml', d, st)
        ok = st%code == 0
        if (.not. ok) return
        do j = 1, size(amps)
            call torsion_period_s(rig_of(d), i1, amps(j), per(j), st)
            ok = ok .and. st%code == 0
        end do
    end subroutine true_periods

    !> ' periods = p(1), p(2), ...' for a deck's &measurement.
    function periods_text(p) result(s)
        real(dp), intent(in) :: p(:)
        character(len=:), allocatable :: s
        integer :: j
        s = ' periods = '//rshort(p(1))
        do j = 2, size(p)
            s = s//', '//rshort(p(j))
        end do
    end function periods_text

    !> x with every digit (es24.16, trimmed): a number as deck text that reads back the same.
    function full_text(x) result(s)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: s
        character(len=32) :: b
        write (b, '(es24.16)') x
        s = trim(adjustl(b))
    end function full_text

end module testing
