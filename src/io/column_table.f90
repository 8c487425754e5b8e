!> The one reader of a measurement's tables (a table of releases, a table of hangs): a table
!! (module tables: separators, quotes, CR LF, a byte order mark, comments) whose columns
!! are known by their names, read and checked by the same rules with the same messages.
!!
!! * The columns: every column named (a header line), each name one of the table's allowed
!!   names (in lower case), none twice; a column absent is the caller's default.
!! * A column the table must have (need): its name, or the first missing of a group that
!!   goes together (up_x, up_y, up_z), and what the table gives of that group.
!! * A value of a row (check_value): one message, 'line L, column NAME = VALUE; allowed:
!!   WHAT'.  A problem of a row that no one column holds (an orientation, points that
!!   coincide): 'line L: WHAT'.  A problem of the table: 'WHAT'.
!! Every message is one line and begins with the table's head (e.g. "&tensor hangs =
!! 'hangs.csv': "), which names the deck's key and the file as given.  No routine stops.
module column_table
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_OK, ERR_DECK
    use text, only: itoa, rshort, quoted, clip, commas, next_word, count_words, lower
    use tables, only: table_t, read_table
    implicit none
    private

    !> A table whose columns are known by name.
    type, public :: column_table_t
        type(table_t) :: tab                    !! the table as read (module tables)
        character(len=:), allocatable :: head   !! the start of every message ('... : ')
        character(len=:), allocatable :: allowed    !! the names allowed, blank-separated
        integer :: nrow = 0                     !! its rows of data
    contains
        procedure :: col => ct_col
        procedure :: has => ct_has
        procedure :: line => ct_line
        procedure :: v => ct_value
        procedure :: text => ct_text
        procedure :: need => ct_need
        procedure :: check_value => ct_check_value
        procedure :: bad_value => ct_bad_value
        procedure :: fail => ct_fail
        procedure :: fail_row => ct_fail_row
    end type column_table_t

    public :: read_column_table

contains

    !> Read the table at `path` and check its columns: each named, known (`allowed`), once.
    !! text_columns: the columns whose fields are text (the table's first line is then its
    !! header).  ERR_DECK: head followed by what is wrong and what is allowed.
    subroutine read_column_table(path, head, allowed, ct, stat, max_rows, text_columns)
        character(len=*), intent(in) :: path        !! the file
        character(len=*), intent(in) :: head        !! the start of every message
        character(len=*), intent(in) :: allowed     !! the names allowed, blank-separated
        type(column_table_t), intent(out) :: ct
        type(status_t), intent(out) :: stat         !! ERR_DECK
        integer, intent(in) :: max_rows             !! most rows (0: no limit)
        character(len=*), intent(in), optional :: text_columns(:)   !! text, not numbers
        integer :: j, k
        ct%head = head
        ct%allowed = allowed
        if (present(text_columns)) then
            call read_table(path, ct%tab, stat, max_rows, text_columns)
        else
            call read_table(path, ct%tab, stat, max_rows)
        end if
        if (stat%code /= STATUS_OK) then
            stat%msg = head//stat%msg
            return
        end if
        ct%nrow = ct%tab%nrow
        do k = 1, ct%tab%ncol
            associate (nm => ct%tab%names(k)%s)
                if (len(nm) == 0) then
                    call ct%fail(stat, 'column '//itoa(k)//' has no name (the table needs '// &
                                 'a header line naming its columns); allowed: '//commas(allowed))
                    return
                end if
                if (index(' '//allowed//' ', ' '//nm//' ') == 0) then
                    call ct%fail(stat, 'unknown column '//quoted(clip(nm))//' (column '// &
                                 itoa(k)//'); allowed: '//commas(allowed))
                    return
                end if
                do j = 1, k - 1
                    if (ct%tab%names(j)%s == nm) then
                        call ct%fail(stat, 'column '//quoted(nm)//' appears twice; '// &
                                     'allowed: each column once')
                        return
                    end if
                end do
            end associate
        end do
    end subroutine read_column_table

    !> The column named `name` (0: absent).
    pure integer function ct_col(ct, name) result(k)
        class(column_table_t), intent(in) :: ct
        character(len=*), intent(in) :: name
        k = ct%tab%column(name)
    end function ct_col

    !> The table has a column named `name`.
    pure logical function ct_has(ct, name)
        class(column_table_t), intent(in) :: ct
        character(len=*), intent(in) :: name
        ct_has = ct%tab%column(name) > 0
    end function ct_has

    !> The line in the file of data row i.
    pure integer function ct_line(ct, i)
        class(column_table_t), intent(in) :: ct
        integer, intent(in) :: i
        ct_line = ct%tab%line(i)
    end function ct_line

    !> The value of column `name` in row i, `default` when the table has no such column.
    pure real(dp) function ct_value(ct, i, name, default) result(v)
        class(column_table_t), intent(in) :: ct
        integer, intent(in) :: i
        character(len=*), intent(in) :: name
        real(dp), intent(in) :: default
        integer :: k
        k = ct%tab%column(name)
        v = default
        if (k > 0) v = ct%tab%v(i, k)
    end function ct_value

    !> The text of column `name` in row i, trimmed ('' when the table has no such text
    !! column).
    pure function ct_text(ct, i, name) result(s)
        class(column_table_t), intent(in) :: ct
        integer, intent(in) :: i
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: s
        integer :: k
        s = ''
        k = ct%tab%column(name)
        if (k == 0 .or. .not. allocated(ct%tab%text)) return
        s = trim(adjustl(ct%tab%text(i, k)%s))
    end function ct_text

    !> The columns `names` (blank-separated: a group that goes together) the table must
    !! have: the first missing is named, with what the table gives of the group and what is
    !! allowed (by default: all of them).
    subroutine ct_need(ct, stat, names, allowed)
        class(column_table_t), intent(in) :: ct
        type(status_t), intent(inout) :: stat
        character(len=*), intent(in) :: names
        character(len=*), intent(in), optional :: allowed
        character(len=:), allocatable :: missing, given, what
        integer :: i1, i2
        if (stat%code /= STATUS_OK) return
        missing = ''
        given = ''
        i2 = 0
        do
            call next_word(names, i2, i1)
            if (i1 == 0) exit
            if (ct%has(names(i1:i2))) then
                if (len(given) > 0) given = given//', '
                given = given//names(i1:i2)
            else if (len(missing) == 0) then
                missing = names(i1:i2)
            end if
        end do
        if (len(missing) == 0) return
        what = 'no column '//quoted(missing)
        if (count_words(names) > 1) what = what//' (the table gives '//given//')'
        if (present(allowed)) then
            call ct%fail(stat, what//'; allowed: '//allowed)
        else
            call ct%fail(stat, what//'; allowed: all of '//commas(names))
        end if
    end subroutine ct_need

    !> The check of one value of row i: when not ok, 'line L, column NAME = V; allowed:
    !! WHAT' (V the value, as rshort writes it).
    subroutine ct_check_value(ct, stat, i, name, v, ok, allowed)
        class(column_table_t), intent(in) :: ct
        type(status_t), intent(inout) :: stat
        integer, intent(in) :: i                    !! the row
        character(len=*), intent(in) :: name        !! its column
        real(dp), intent(in) :: v                   !! the value
        logical, intent(in) :: ok                   !! the value is allowed
        character(len=*), intent(in) :: allowed     !! what is allowed
        if (stat%code /= STATUS_OK .or. ok) return
        call ct%bad_value(stat, i, name, rshort(v), allowed)
    end subroutine ct_check_value

    !> A value of row i refused: 'line L, column NAME = VALUE; allowed: WHAT'.
    subroutine ct_bad_value(ct, stat, i, name, value, allowed)
        class(column_table_t), intent(in) :: ct
        type(status_t), intent(inout) :: stat
        integer, intent(in) :: i
        character(len=*), intent(in) :: name, value, allowed
        call ct%fail(stat, 'line '//itoa(ct%tab%line(i))//', column '//trim(lower(name))// &
                     ' = '//trim(value)//'; allowed: '//allowed)
    end subroutine ct_bad_value

    !> A problem of the table: head, then what.
    subroutine ct_fail(ct, stat, what)
        class(column_table_t), intent(in) :: ct
        type(status_t), intent(inout) :: stat
        character(len=*), intent(in) :: what
        call set_error(stat, ERR_DECK, ct%head//what)
    end subroutine ct_fail

    !> A problem of row i that no one column holds: 'line L: WHAT'.
    subroutine ct_fail_row(ct, stat, i, what)
        class(column_table_t), intent(in) :: ct
        type(status_t), intent(inout) :: stat
        integer, intent(in) :: i
        character(len=*), intent(in) :: what
        call ct%fail(stat, 'line '//itoa(ct%tab%line(i))//': '//what)
    end subroutine ct_fail_row

end module column_table
