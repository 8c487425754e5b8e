!> One line of progress with an estimate of the time left, for long analyses (chart sweeps,
!! work-precision runs; later design sweeps, Monte Carlo, fits).  It is drawn on standard
!! error only when standard error is a terminal (isatty(2)), rewritten in place with a
!! carriage return at most every REDRAW_SECONDS and erased at the end, so a log file or a
!! pipe receives nothing from it.
!!
!! Usage:
!!     type(progress_t) :: pr
!!     call pr%start('box_chart: chart', npoints)
!!     ... call pr%tick()   (once per item done; from one thread at a time)
!!     call pr%finish()
module progress
    use, intrinsic :: iso_c_binding, only: c_int
    use, intrinsic :: iso_fortran_env, only: error_unit, int64
    use kinds, only: dp
    use text, only: fixed, itoa
    implicit none
    private

    !> The progress of one analysis.
    type, public :: progress_t
        private
        character(len=:), allocatable :: label
        integer :: total = 0                    !! items to do
        integer :: done = 0                     !! items done
        integer(int64) :: c0 = 0, rate = 1     !! system_clock at start, ticks per second
        integer(int64) :: last = 0              !! system_clock at the last redraw
        logical :: shown = .false.              !! drawing (stderr is a terminal)
        integer :: width = 0                    !! length of the line drawn
    contains
        procedure :: start => progress_start
        procedure :: tick => progress_tick
        procedure :: finish => progress_finish
        procedure :: line => progress_line
    end type progress_t

    !> A run that may take long says so once, on one line of standard error, after
    !! note_after() seconds (default NOTE_SECONDS), whether or not it is a terminal: what it
    !! is doing and, at the pace so far, how much longer it will take (the rule: a deck
    !! ends within 10 s, or refuses at once, or says within 10 s what it is doing).
    !!     call pace%start('bifilar: note: DECK: simulate', tau0, tau_end, 'tau')
    !!     ... call pace%check(tau)      (often; it reads the clock every 64 calls)
    type, public :: pace_t
        character(len=:), allocatable :: label  !! 'bifilar: note: DECK: what'
        character(len=:), allocatable :: unit   !! what x counts ('tau')
        real(dp) :: x0 = 0.0_dp, x1 = 1.0_dp    !! the run's start and end
        real(dp) :: after = 5.0_dp              !! seconds before the note
        integer(int64) :: c0 = 0, rate = 1
        integer :: calls = 0
        integer :: every = 64                   !! calls between readings of the clock
        logical :: armed = .false.              !! started, not yet said
    contains
        procedure :: start => pace_start
        procedure :: check => pace_check
    end type pace_t

    public :: stderr_is_terminal, note_after, say_note, duration

    !> Seconds a run goes on before it says what it is doing (BIFILAR_NOTE_AFTER overrides,
    !! for tests).
    real(dp), parameter :: NOTE_SECONDS = 5.0_dp

    !> Least time between two redraws (s).
    real(dp), parameter :: REDRAW_SECONDS = 0.5_dp

    interface
        !> C library isatty(3).
        integer(c_int) function c_isatty(fd) bind(C, name='isatty')
            import :: c_int
            integer(c_int), value :: fd
        end function c_isatty
    end interface

contains

    !> True when standard error (file descriptor 2) is a terminal.
    logical function stderr_is_terminal()
        stderr_is_terminal = c_isatty(2_c_int) == 1
    end function stderr_is_terminal

    !> Begin: `label` names the work (e.g. 'box_chart: chart'), `total` counts its items.
    subroutine progress_start(self, label, total, force)
        class(progress_t), intent(inout) :: self
        character(len=*), intent(in) :: label       !! what is being done
        integer, intent(in) :: total                !! number of items
        logical, intent(in), optional :: force      !! draw even when stderr is no terminal
        self%label = label
        self%total = max(total, 1)
        self%done = 0
        self%width = 0
        call system_clock(self%c0, self%rate)
        self%last = self%c0
        self%shown = stderr_is_terminal()
        if (present(force)) self%shown = self%shown .or. force
    end subroutine progress_start

    !> `n` more items done (default 1); redraws the line when due.
    subroutine progress_tick(self, n)
        class(progress_t), intent(inout) :: self
        integer, intent(in), optional :: n          !! items just done
        integer(int64) :: c
        character(len=:), allocatable :: s
        if (present(n)) then
            self%done = self%done + n
        else
            self%done = self%done + 1
        end if
        if (.not. self%shown) return
        call system_clock(c)
        if (real(c - self%last, dp) < REDRAW_SECONDS*real(self%rate, dp) .and. &
            self%done < self%total) return
        self%last = c
        s = self%line(real(c - self%c0, dp)/real(self%rate, dp))
        write (error_unit, '(a)', advance='no') achar(13)//s// &
            repeat(' ', max(0, self%width - len(s)))
        flush (error_unit)
        self%width = len(s)
    end subroutine progress_tick

    !> End: the line is erased (nothing stays on the terminal).
    subroutine progress_finish(self)
        class(progress_t), intent(inout) :: self
        if (self%shown .and. self%width > 0) then
            write (error_unit, '(a)', advance='no') achar(13)//repeat(' ', self%width)// &
                achar(13)
            flush (error_unit)
        end if
        self%width = 0
        self%shown = .false.
    end subroutine progress_finish

    !> The progress line after `elapsed` seconds: 'LABEL: 12 of 40 (30%), ETA 1 min 4 s'.
    function progress_line(self, elapsed) result(s)
        class(progress_t), intent(in) :: self
        real(dp), intent(in) :: elapsed             !! seconds since start
        character(len=:), allocatable :: s
        character(len=64) :: buf
        real(dp) :: left
        write (buf, '(i0,a,i0,a,i0,a)') self%done, ' of ', self%total, ' (', &
            (100*self%done)/self%total, '%)'
        s = self%label//': '//trim(buf)
        if (self%done > 0 .and. self%done < self%total) then
            left = elapsed*real(self%total - self%done, dp)/real(self%done, dp)
            s = s//', ETA '//duration(left)
        end if
    end function progress_line

    !> Seconds before a long run says what it is doing: NOTE_SECONDS, or the environment's
    !! BIFILAR_NOTE_AFTER (a number >= 0) when set.
    function note_after() result(t)
        real(dp) :: t
        character(len=32) :: v
        integer :: ios, n
        t = NOTE_SECONDS
        call get_environment_variable('BIFILAR_NOTE_AFTER', v, n)
        if (n < 1 .or. n > len(v)) return
        read (v, *, iostat=ios) t
        if (ios /= 0 .or. .not. (t >= 0.0_dp .and. t <= 1.0e6_dp)) t = NOTE_SECONDS
    end function note_after

    !> One line on standard error: 'bifilar: note: DECK: TEXT' (the run goes on).
    subroutine say_note(deck_path, text)
        character(len=*), intent(in) :: deck_path   !! the deck as given
        character(len=*), intent(in) :: text        !! what it is doing, how long it takes
        write (error_unit, '(a)') 'bifilar: note: '//deck_path//': '//text
        flush (error_unit)
    end subroutine say_note

    !> Begin a run from x0 to x1 (in `unit`s), `label` its note's start.
    subroutine pace_start(self, label, x0, x1, unit, every)
        class(pace_t), intent(inout) :: self
        character(len=*), intent(in) :: label       !! 'bifilar: note: DECK: simulate'
        real(dp), intent(in) :: x0, x1              !! the run's start and end
        character(len=*), intent(in) :: unit        !! what x counts
        integer, intent(in), optional :: every      !! calls between clock readings (64)
        self%every = 64
        if (present(every)) self%every = max(1, every)
        self%label = label
        self%unit = unit
        self%x0 = x0
        self%x1 = x1
        self%after = note_after()
        self%calls = 0
        call system_clock(self%c0, self%rate)
        self%armed = x1 > x0
    end subroutine pace_start

    !> The run is at x: after note_after() seconds, one line with the pace so far.
    subroutine pace_check(self, x)
        class(pace_t), intent(inout) :: self
        real(dp), intent(in) :: x                   !! how far the run is
        integer(int64) :: c
        real(dp) :: el, f
        character(len=:), allocatable :: s
        if (.not. self%armed) return
        self%calls = self%calls + 1
        if (mod(self%calls, self%every) /= min(1, self%every - 1)) return
        call system_clock(c)
        el = real(c - self%c0, dp)/real(self%rate, dp)
        if (el < self%after) return
        self%armed = .false.
        f = (x - self%x0)/(self%x1 - self%x0)
        if (self%unit == 'points') then
            s = self%label//': '//itoa(nint(x))//' of '//itoa(nint(self%x1))//' points '// &
                'after '//duration(el)
        else
            s = self%label//': '//self%unit//' = '//fixed(x, 4)//' of '//fixed(self%x1, 4)// &
                ' after '//duration(el)
        end if
        if (f > 0.0_dp .and. f < 1.0_dp) then
            s = s//'; at this pace about '//duration(el*(1.0_dp - f)/f)//' more'
        else
            s = s//'; the end cannot be told yet'
        end if
        write (error_unit, '(a)') s
        flush (error_unit)
    end subroutine pace_check

    !> A duration for people: 8 s, 2 min 5 s, 1 h 3 min.
    function duration(secs) result(s)
        real(dp), intent(in) :: secs
        character(len=:), allocatable :: s
        character(len=40) :: buf
        integer :: t
        t = nint(max(0.0_dp, min(secs, 3.6e7_dp)))
        if (t < 60) then
            write (buf, '(i0,a)') t, ' s'
        else if (t < 3600) then
            write (buf, '(i0,a,i0,a)') t/60, ' min ', mod(t, 60), ' s'
        else
            write (buf, '(i0,a,i0,a)') t/3600, ' h ', mod(t, 3600)/60, ' min'
        end if
        s = trim(buf)
    end function duration

end module progress
