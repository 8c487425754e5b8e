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

    public :: stderr_is_terminal

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
