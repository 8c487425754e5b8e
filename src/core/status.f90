!> Status objects returned by every routine that can fail.  No library module stops:
!! a routine fills a status_t and returns; only the main program decides to exit.
module status
    implicit none
    private

    !> Status codes.  The main program maps them to exit codes (see README):
    !! bad input -> 2, numerical failure -> 3, model no longer valid -> 4, I/O -> 5.
    integer, parameter, public :: STATUS_OK = 0
    integer, parameter, public :: ERR_DECK = 2        !! bad input deck (any variable)
    integer, parameter, public :: ERR_NUMERIC = 3     !! integrator or linear algebra failure
    integer, parameter, public :: ERR_MODEL = 4       !! model no longer valid (slack cable, singular chart)
    integer, parameter, public :: ERR_IO = 5          !! cannot write or rename an output file

    type, public :: status_t
        integer :: code = STATUS_OK                   !! STATUS_OK or one of the ERR_* codes
        character(len=:), allocatable :: msg          !! what went wrong, where, what is allowed
    end type status_t

    public :: set_error, is_ok

contains

    !> Fill stat with a code and a message.
    pure subroutine set_error(stat, code, msg)
        type(status_t), intent(inout) :: stat   !! status to fill
        integer, intent(in) :: code             !! one of the ERR_* codes
        character(len=*), intent(in) :: msg     !! message for the user
        stat%code = code
        stat%msg = msg
    end subroutine set_error

    !> True when stat carries no error.
    pure logical function is_ok(stat)
        type(status_t), intent(in) :: stat     !! status to test
        is_ok = stat%code == STATUS_OK
    end function is_ok

end module status
