!> What every part of the input deck shares: the base type of a namelist group
!! (deck_group_t) and the deck's source (deck_source_t).
!!
!! Each namelist group of the deck is a type extending deck_group_t, written in the layer
!! that uses it (the rig's groups in runs/rig_groups, the measurement's in
!! measure/measure_groups, those of one analysis in deck/analysis_groups): its keys with
!! their defaults, its name and its spec (the variables' kinds, for explaining a read
!! error: module namelist_text), its read from the group's text, its echo, and, bound by
!! each type with the arguments it needs, its check (which never changes a value) and its
!! normalisation (a separate, named step).  Module deck composes them.
module deck_base
    use kinds, only: dp
    implicit none
    private

    !> A deck's source: what a sweep fingerprints and sends to the other ranks of an MPI run
    !! (module sweep_engine), and how the deck is named in files and messages.
    type, public :: deck_source_t
        character(len=:), allocatable :: path        !! deck file as given
        character(len=:), allocatable :: name        !! file name without directory and .nml
        character(len=:), allocatable :: text        !! the deck file's lines, joined by newlines
    end type deck_source_t

    !> One namelist group of a deck.  `given` records the keys the deck gave itself, for the
    !! keys a group tracks (the physical inputs a measuring deck must give: gave).
    type, abstract, public :: deck_group_t
        character(len=:), allocatable :: given      !! ' key key ... ' (those tracked)
    contains
        !> the group's name, lower case (e.g. 'suspension')
        procedure(group_text_i), deferred, nopass :: name
        !> its variables with their kinds and sizes (module namelist_text), for explaining
        !! a read error
        procedure(group_text_i), deferred, nopass :: spec
        !> read the group from its text as one record ('&name ... /'): the values the deck
        !! gives replace the defaults
        procedure(group_read_i), deferred :: read_text
        !> the group's line of the echo: '# &name key = value, ... /'
        procedure(group_echo_i), deferred :: echo
        procedure :: gave
        procedure :: note_given
    end type deck_group_t

    abstract interface
        function group_text_i() result(s)
            character(len=:), allocatable :: s
        end function group_text_i
        subroutine group_read_i(self, rec, ios, msg)
            import :: deck_group_t
            class(deck_group_t), intent(inout) :: self  !! defaults in, values read out
            character(len=*), intent(in) :: rec         !! the group as one record
            integer, intent(out) :: ios                 !! iostat of the namelist read
            character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        end subroutine group_read_i
        function group_echo_i(self) result(line)
            import :: deck_group_t
            class(deck_group_t), intent(in) :: self
            character(len=:), allocatable :: line
        end function group_echo_i
    end interface

    !> The value a tracked real has before the namelist read: still there after it, the deck
    !! did not give it.
    real(dp), parameter, public :: NOT_GIVEN = -huge(1.0_dp)

    public :: record_in_folder

contains

    !> True when the deck gave the tracked key `key` of this group itself.
    pure logical function gave(self, key)
        class(deck_group_t), intent(in) :: self
        character(len=*), intent(in) :: key         !! e.g. 'cg_depth'
        gave = .false.
        if (allocated(self%given)) gave = index(self%given, ' '//key//' ') > 0
    end function gave

    !> Record that the deck gave the tracked key `key` (a group's read_text).
    pure subroutine note_given(self, key)
        class(deck_group_t), intent(inout) :: self
        character(len=*), intent(in) :: key
        if (.not. allocated(self%given)) self%given = ' '
        if (index(self%given, ' '//key//' ') == 0) self%given = self%given//key//' '
    end subroutine note_given

    !> A file named in a deck (a record, a table): as given when absolute, else relative to
    !! the deck's folder.
    pure function record_in_folder(deck_path, record) result(p)
        character(len=*), intent(in) :: deck_path   !! the deck as given
        character(len=*), intent(in) :: record      !! the file as the deck names it
        character(len=:), allocatable :: p
        integer :: i
        p = trim(adjustl(record))
        if (p(1:1) == '/') return
        i = index(deck_path, '/', back=.true.)
        if (i > 0) p = deck_path(1:i)//p
    end function record_in_folder

end module deck_base
