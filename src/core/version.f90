!> The program's version, as `bifilar --version` prints it and every certificate states it.
module version
    implicit none
    private
    character(len=*), parameter, public :: BIFILAR_VERSION = '1.1'
end module version
