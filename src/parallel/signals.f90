!> What a sweep does when it is stopped by SIGINT, SIGTERM or SIGHUP (mpirun sends SIGTERM to
!! every rank when one dies): the handler removes the run's staged files (and the file being
!! written, while there is one), writes one line to standard error and exits with status
!! 128 + the signal, through _exit(2): nothing else of the program runs.
!!
!! `install_signals` prepares the line and the paths to remove, then installs the handler;
!! `remove_signals` puts back the handlers there were before.  The line is the text given
!! up to the signal's number, the number, and one of two endings: the first while no
!! checkpoint is kept, the second once `signals_kept` says one is.  `signals_writing` names
!! a file being written (a checkpoint's temporary file), removed too until `signals_written`.
!!
!! Module state: the module keeps what the handler needs in module variables, because a
!! signal handler is given nothing but the signal's number: everything else must be
!! prepared beforehand where it can find it (the line's parts and a buffer to put it
!! together in, the paths to remove as C strings, which ending applies, whether a file is
!! being written), and the handlers it replaces must be kept to be put back.  The handler
!! only reads that state and calls write(2), unlink(2) and _exit(2), all async-signal-safe.
!! The line is one write(2), so that it is whole or absent (mpirun sends SIGKILL soon after
!! its SIGTERM).
module signals
    use, intrinsic :: iso_c_binding, only: c_int, c_char, c_funptr, c_funloc, c_null_char, &
        c_size_t
    implicit none
    private

    public :: install_signals, remove_signals, signals_kept, signals_writing, signals_written

    !> The signals handled: SIGINT, SIGTERM, SIGHUP.
    integer(c_int), parameter :: HANDLED(3) = [2_c_int, 15_c_int, 1_c_int]

    !> The line up to the signal's number (null-terminated).
    character(kind=c_char), allocatable, save :: sig_head(:)
    !> The line's endings after the number, with its newline: (:, 1) while no checkpoint is
    !! kept, (:, 2) once one is; their lengths; the one that applies (1 or 2).
    character(kind=c_char), allocatable, save :: sig_tail(:, :)
    integer, save :: sig_tail_len(2) = 0
    integer, save :: sig_kept = 1
    !> The line as the handler writes it, in one write(2): head, signal number, tail.
    character(kind=c_char), allocatable, save :: sig_msg(:)
    !> The staged files to remove (null-terminated paths, one a column) and their number.
    character(kind=c_char), allocatable, save :: sig_tmp(:, :)
    integer, save :: sig_ntmp = 0
    !> The file being written (null-terminated), removed too while sig_writing = 1.
    character(kind=c_char), allocatable, save :: sig_writing_path(:)
    integer, save :: sig_writing = 0
    !> The handlers there were before install_signals.
    type(c_funptr), save :: sig_old(3)

    interface
        type(c_funptr) function c_signal(sig, handler) bind(C, name='signal')
            import :: c_int, c_funptr
            integer(c_int), value :: sig
            type(c_funptr), value :: handler
        end function c_signal
        integer(c_size_t) function c_write(fd, buf, n) bind(C, name='write')
            import :: c_int, c_char, c_size_t
            integer(c_int), value :: fd
            character(kind=c_char), dimension(*), intent(in) :: buf
            integer(c_size_t), value :: n
        end function c_write
        integer(c_int) function c_unlink_sig(path) bind(C, name='unlink')
            import :: c_int, c_char
            character(kind=c_char), dimension(*), intent(in) :: path
        end function c_unlink_sig
        subroutine c_exit_now(status) bind(C, name='_exit')
            import :: c_int
            integer(c_int), value :: status
        end subroutine c_exit_now
    end interface

contains

    !> On SIGINT, SIGTERM or SIGHUP from now on: remove the files `paths` (and the file being
    !! written), write head, the signal's number and an ending (tail_none, or tail_kept when
    !! a checkpoint is kept) as one line, and exit with 128 + the signal.
    subroutine install_signals(head, tail_none, tail_kept, kept, paths)
        character(len=*), intent(in) :: head        !! the line up to the signal's number
        character(len=*), intent(in) :: tail_none   !! its ending while no checkpoint is kept
        character(len=*), intent(in) :: tail_kept   !! its ending once one is
        logical, intent(in) :: kept                 !! a checkpoint is kept already
        !> The files to remove (the run's staged files; trailing blanks are not part of a
        !! path, blank ones are skipped)
        character(len=*), intent(in) :: paths(:)
        integer :: k, n, m
        sig_kept = merge(2, 1, kept)
        call to_c(head, sig_head)
        n = max(len(tail_kept), len(tail_none)) + 1
        if (allocated(sig_tail)) deallocate (sig_tail)
        allocate (sig_tail(n, 2))
        sig_tail = c_null_char
        do k = 1, len(tail_none)
            sig_tail(k, 1) = tail_none(k:k)
        end do
        sig_tail(len(tail_none) + 1, 1) = achar(10)
        do k = 1, len(tail_kept)
            sig_tail(k, 2) = tail_kept(k:k)
        end do
        sig_tail(len(tail_kept) + 1, 2) = achar(10)
        sig_tail_len = [len(tail_none) + 1, len(tail_kept) + 1]
        if (allocated(sig_msg)) deallocate (sig_msg)
        allocate (sig_msg(len(head) + 4 + maxval(sig_tail_len)))
        sig_msg = c_null_char
        sig_ntmp = 0
        if (allocated(sig_tmp)) deallocate (sig_tmp)
        allocate (sig_tmp(len(paths) + 1, max(1, size(paths))))
        sig_tmp = c_null_char
        do k = 1, size(paths)
            m = len_trim(paths(k))
            if (m == 0) cycle
            sig_ntmp = sig_ntmp + 1
            do n = 1, m
                sig_tmp(n, sig_ntmp) = paths(k)(n:n)
            end do
        end do
        do k = 1, size(HANDLED)
            sig_old(k) = c_signal(HANDLED(k), c_funloc(on_signal))
        end do
    end subroutine install_signals

    !> Put back the handlers there were before install_signals.
    subroutine remove_signals()
        type(c_funptr) :: prev
        integer :: k
        do k = 1, size(HANDLED)
            prev = c_signal(HANDLED(k), sig_old(k))
        end do
    end subroutine remove_signals

    !> A checkpoint is kept from now on: the handler's line ends with tail_kept.
    subroutine signals_kept()
        sig_kept = 2
    end subroutine signals_kept

    !> The file at path is being written: the handler removes it too, until signals_written.
    subroutine signals_writing(path)
        character(len=*), intent(in) :: path        !! its (temporary) path
        call to_c(path, sig_writing_path)
        sig_writing = 1
    end subroutine signals_writing

    !> The file of signals_writing is written (or gone): the handler leaves it alone.
    subroutine signals_written()
        sig_writing = 0
    end subroutine signals_written

    !> A string as a null-terminated C array.
    subroutine to_c(s, a)
        character(len=*), intent(in) :: s           !! the string
        character(kind=c_char), allocatable, intent(inout) :: a(:)  !! its characters, then null
        integer :: k
        if (allocated(a)) deallocate (a)
        allocate (a(len(s) + 1))
        do k = 1, len(s)
            a(k) = s(k:k)
        end do
        a(len(s) + 1) = c_null_char
    end subroutine to_c

    !> The signal handler (async-signal-safe: write, unlink, _exit only).
    subroutine on_signal(sig) bind(C)
        integer(c_int), value :: sig                !! the signal's number
        integer(c_size_t) :: rc
        integer(c_int) :: rcu, s
        integer :: k, nd, n
        character(kind=c_char) :: digits(4)
        do k = 1, sig_ntmp
            rcu = c_unlink_sig(sig_tmp(:, k))
        end do
        if (sig_writing == 1) rcu = c_unlink_sig(sig_writing_path)
        s = sig
        nd = 0
        do while (nd < 4)
            nd = nd + 1
            digits(5 - nd) = achar(48 + mod(s, 10))
            s = s/10
            if (s == 0) exit
        end do
        n = size(sig_head) - 1
        sig_msg(1:n) = sig_head(1:n)
        sig_msg(n + 1:n + nd) = digits(5 - nd:4)
        n = n + nd
        sig_msg(n + 1:n + sig_tail_len(sig_kept)) = sig_tail(1:sig_tail_len(sig_kept), sig_kept)
        n = n + sig_tail_len(sig_kept)
        rc = c_write(2_c_int, sig_msg, int(n, c_size_t))
        call c_exit_now(128_c_int + sig)
    end subroutine on_signal

end module signals
