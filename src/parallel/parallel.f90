!> Message passing between the processes (ranks) of a run, serial build: one rank, no
!! messages.  The MPI build compiles src/parallel_mpi.f90 instead, a module of the same
!! name and interface on OpenMPI; everything that runs over ranks (module sweep_engine) is
!! written once against this interface.
!!
!! The interface: par_start / par_stop begin and end the run's message passing; par_rank
!! (0 .. par_ranks() - 1) and par_ranks; par_post sends an array of reals without waiting
!! (the module keeps a copy until it is delivered); par_poll asks, without waiting, whether
!! a message has arrived and how long it is; par_recv receives the message par_poll found.
!! Payloads are real(dp) arrays (integers below 2**53 travel exactly as reals).  Only one
!! thread of a rank calls these at a time (the sweep engine calls them inside one OpenMP
!! critical section).
module parallel
    use kinds, only: dp
    use status, only: status_t, STATUS_OK
    use unused_arg, only: unused
    implicit none
    private

    public :: par_start, par_stop, par_rank, par_ranks, par_post, par_poll, par_recv
    public :: par_library

    !> par_poll's `from` for a message from any rank.
    integer, parameter, public :: PAR_ANY = -1

contains

    !> Begin (nothing to do in the serial build).
    subroutine par_start(stat)
        type(status_t), intent(out) :: stat         !! always OK here
        stat%code = STATUS_OK
    end subroutine par_start

    !> End (nothing to do in the serial build).
    subroutine par_stop()
    end subroutine par_stop

    !> This process's rank: always 0.
    integer function par_rank()
        par_rank = 0
    end function par_rank

    !> Number of ranks: always 1.
    integer function par_ranks()
        par_ranks = 1
    end function par_ranks

    !> Send buf to rank dest: there is no other rank in the serial build, nothing is sent.
    subroutine par_post(dest, tag, buf)
        integer, intent(in) :: dest                 !! receiving rank
        integer, intent(in) :: tag                  !! message kind
        real(dp), intent(in) :: buf(:)              !! payload
        call unused(dest)
        call unused(tag)
        call unused(buf)
    end subroutine par_post

    !> Whether a message from `from` (or PAR_ANY) has arrived: never in the serial build.
    subroutine par_poll(from, src, tag, n, found)
        integer, intent(in) :: from                 !! sending rank, or PAR_ANY
        integer, intent(out) :: src                 !! its sender
        integer, intent(out) :: tag                 !! its kind
        integer, intent(out) :: n                   !! its length (reals)
        logical, intent(out) :: found               !! a message is there
        src = from
        tag = -1
        n = 0
        found = .false.
    end subroutine par_poll

    !> Receive the message par_poll found (never called in the serial build).
    subroutine par_recv(src, tag, buf)
        integer, intent(in) :: src                  !! its sender
        integer, intent(in) :: tag                  !! its kind
        real(dp), intent(out) :: buf(:)             !! its payload (length from par_poll)
        call unused(src)
        call unused(tag)
        buf = 0.0_dp
    end subroutine par_recv

    !> The message-passing library: 'none (serial build)'.
    function par_library() result(s)
        character(len=:), allocatable :: s
        s = 'none (serial build)'
    end function par_library

end module parallel
