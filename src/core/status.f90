!> Status objects returned by every routine that can fail, and the one table of status codes.
!! No library module stops: a routine fills a status_t and returns; only the main program
!! decides to exit, with the exit status the table gives for the code.
!!
!! The table (STATUS_TABLE): every code the program uses, its name, its exit status and
!! what it means.  Exit statuses: 2 bad input, 3 numerical failure, 4 the model no longer
!! holds, 5 an output file cannot be written (doc/output.md; 0 success, 1 usage and 128 + n
!! a signal are the main program's).
module status
    implicit none
    private

    ! ---- the codes (STATUS_TABLE below gives each its exit status and meaning)
    integer, parameter, public :: STATUS_OK = 0
    integer, parameter, public :: ERR_DECK = 2        !! bad input deck (any variable)
    integer, parameter, public :: ERR_NUMERIC = 3     !! integrator or linear algebra failure
    integer, parameter, public :: ERR_MODEL = 4       !! model no longer valid (slack cable, singular chart)
    integer, parameter, public :: ERR_IO = 5          !! cannot write or rename an output file
    ! LSODA (module lsoda)
    integer, parameter, public :: LSODA_ERR_MAX_STEPS = 11          !! max_steps taken in one call
    integer, parameter, public :: LSODA_ERR_TOO_MUCH_ACCURACY = 12  !! tolerance below roundoff
    integer, parameter, public :: LSODA_ERR_ERROR_TEST = 13         !! repeated error-test failures
    integer, parameter, public :: LSODA_ERR_CONVERGENCE = 14        !! repeated corrector failures
    integer, parameter, public :: LSODA_ERR_ILLEGAL_INPUT = 15      !! bad argument
    integer, parameter, public :: LSODA_ERR_SINGULAR = 16           !! singular iteration matrix
    ! Radau IIA (module radau)
    integer, parameter, public :: RADAU_ERR_MAX_STEPS = 21          !! max_steps in one call
    integer, parameter, public :: RADAU_ERR_TOO_MUCH_ACCURACY = 22  !! tolerance below roundoff
    integer, parameter, public :: RADAU_ERR_STEP_TOO_SMALL = 23     !! h below roundoff of t
    integer, parameter, public :: RADAU_ERR_ILLEGAL_INPUT = 25      !! bad argument
    integer, parameter, public :: RADAU_ERR_SINGULAR = 26           !! singular iteration matrix
    ! the elastic model's generalized coordinates (module elastic_gen)
    integer, parameter, public :: GEN_ERR_CHART = 31  !! the generalized chart degenerates here

    !> Exit statuses of the program.
    integer, parameter, public :: EXIT_OK = 0, EXIT_USAGE = 1, EXIT_DECK = 2, &
        EXIT_NUMERIC = 3, EXIT_MODEL = 4, EXIT_IO = 5

    !> One row of the table.
    type, public :: status_code_t
        integer :: code                     !! the code
        integer :: exit_status              !! the program's exit status for it
        character(len=28) :: name           !! its name in the sources
        character(len=40) :: meaning        !! what it means (the kind of an error line)
    end type status_code_t

    !> Every code of the program.
    type(status_code_t), parameter, public :: STATUS_TABLE(*) = [ &
        status_code_t(STATUS_OK, EXIT_OK, 'STATUS_OK', 'success'), &
        status_code_t(ERR_DECK, EXIT_DECK, 'ERR_DECK', 'bad input'), &
        status_code_t(ERR_NUMERIC, EXIT_NUMERIC, 'ERR_NUMERIC', 'numerical failure'), &
        status_code_t(ERR_MODEL, EXIT_MODEL, 'ERR_MODEL', 'model no longer valid'), &
        status_code_t(ERR_IO, EXIT_IO, 'ERR_IO', 'cannot write output'), &
        status_code_t(LSODA_ERR_MAX_STEPS, EXIT_NUMERIC, 'LSODA_ERR_MAX_STEPS', &
                      'numerical failure'), &
        status_code_t(LSODA_ERR_TOO_MUCH_ACCURACY, EXIT_NUMERIC, 'LSODA_ERR_TOO_MUCH_ACCURACY', &
                      'numerical failure'), &
        status_code_t(LSODA_ERR_ERROR_TEST, EXIT_NUMERIC, 'LSODA_ERR_ERROR_TEST', &
                      'numerical failure'), &
        status_code_t(LSODA_ERR_CONVERGENCE, EXIT_NUMERIC, 'LSODA_ERR_CONVERGENCE', &
                      'numerical failure'), &
        status_code_t(LSODA_ERR_ILLEGAL_INPUT, EXIT_NUMERIC, 'LSODA_ERR_ILLEGAL_INPUT', &
                      'numerical failure'), &
        status_code_t(LSODA_ERR_SINGULAR, EXIT_NUMERIC, 'LSODA_ERR_SINGULAR', &
                      'numerical failure'), &
        status_code_t(RADAU_ERR_MAX_STEPS, EXIT_NUMERIC, 'RADAU_ERR_MAX_STEPS', &
                      'numerical failure'), &
        status_code_t(RADAU_ERR_TOO_MUCH_ACCURACY, EXIT_NUMERIC, 'RADAU_ERR_TOO_MUCH_ACCURACY', &
                      'numerical failure'), &
        status_code_t(RADAU_ERR_STEP_TOO_SMALL, EXIT_NUMERIC, 'RADAU_ERR_STEP_TOO_SMALL', &
                      'numerical failure'), &
        status_code_t(RADAU_ERR_ILLEGAL_INPUT, EXIT_NUMERIC, 'RADAU_ERR_ILLEGAL_INPUT', &
                      'numerical failure'), &
        status_code_t(RADAU_ERR_SINGULAR, EXIT_NUMERIC, 'RADAU_ERR_SINGULAR', &
                      'numerical failure'), &
        status_code_t(GEN_ERR_CHART, EXIT_NUMERIC, 'GEN_ERR_CHART', 'numerical failure')]

    type, public :: status_t
        integer :: code = STATUS_OK                   !! STATUS_OK or one of the ERR_* codes
        character(len=:), allocatable :: msg          !! what went wrong, where, what is allowed
    end type status_t

    public :: set_error, is_ok, exit_status_of, status_meaning

contains

    !> Fill stat with a code and a message.
    pure subroutine set_error(stat, code, msg)
        type(status_t), intent(inout) :: stat   !! status to fill
        integer, intent(in) :: code             !! one of the codes of STATUS_TABLE
        character(len=*), intent(in) :: msg     !! message for the user
        stat%code = code
        stat%msg = msg
    end subroutine set_error

    !> True when stat carries no error.
    pure logical function is_ok(stat)
        type(status_t), intent(in) :: stat     !! status to test
        is_ok = stat%code == STATUS_OK
    end function is_ok

    !> The exit status of a code (STATUS_TABLE; a code not in it counts as a numerical
    !! failure, as the codes a right-hand side may invent do).
    pure integer function exit_status_of(code) result(e)
        integer, intent(in) :: code             !! status_t%code
        integer :: i
        e = EXIT_NUMERIC
        do i = 1, size(STATUS_TABLE)
            if (STATUS_TABLE(i)%code == code) e = STATUS_TABLE(i)%exit_status
        end do
    end function exit_status_of

    !> What a code means, the kind of the program's error line ('bad input', ...).
    pure function status_meaning(code) result(s)
        integer, intent(in) :: code             !! status_t%code
        character(len=:), allocatable :: s
        integer :: i
        s = 'numerical failure'
        do i = 1, size(STATUS_TABLE)
            if (STATUS_TABLE(i)%code == code) s = trim(STATUS_TABLE(i)%meaning)
        end do
    end function status_meaning

end module status
