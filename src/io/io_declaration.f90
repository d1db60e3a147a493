!> One input variable, declared once: the groups that hold it, its name,
!> type, unit, default (as text), what it may be (a range of numbers or a
!> set of words) and its meaning in one line. The tables of declarations
!> (io_declarations_*) are the one place these are written: the reader of
!> every group takes its names, bounds, units and words from them
!> (io_input), `slidesim --input-reference` writes the tables of
!> docs/inputs.md from them (io_input_declarations), and `slidesim
!> --default-input SCENARIO` the comments of its template (io_templates).
module io_declaration
  use base_kinds, only: wp
  use base_text, only: format_real, format_integer
  implicit none (type, external)
  private
  public :: declaration_t, bound_text, allowed_text, in_groups, words_joined
  public :: VALUE_REAL, VALUE_INTEGER, VALUE_LOGICAL, VALUE_WORDS

  !> What a variable's values are: numbers (a range), whole numbers (a
  !> range), logicals, or texts (a set of words, or any text when `choices`
  !> is empty).
  integer, parameter :: VALUE_REAL = 1, VALUE_INTEGER = 2, VALUE_LOGICAL = 3, VALUE_WORDS = 4

  !> One variable. A real lies in [low, high] (or (low, high] with
  !> open_low); a whole number in [low, high]; `choices` are blank-separated
  !> words. `shape` says how many values it takes when not one ('3', 'list
  !> of at most 500', 'per limit'); `groups` is blank-separated: a variable
  !> shared by several groups (&rider mass, &sweep mass) is declared once.
  !> `range_of` ('rider mu') gives a variable of another name the range (and,
  !> without a unit of its own, the unit) of that declaration: the same
  !> quantity in another role (&identify twin_mu, the true mu_D of a twin
  !> experiment).
  type :: declaration_t
    character(len=48) :: groups = ''
    character(len=24) :: name = ''
    character(len=24) :: range_of = ''
    integer :: kind = VALUE_REAL
    character(len=32) :: shape = ''
    character(len=40) :: unit = ''
    character(len=48) :: default = ''
    real(wp) :: low = 0, high = 0
    logical :: open_low = .false.
    character(len=240) :: choices = ''
    character(len=240) :: meaning = ''
  end type declaration_t

contains

  !> A bound for messages and tables: whole numbers plainly, others as format_real.
  pure function bound_text(x) result(text)
    real(wp), intent(in) :: x
    character(len=:), allocatable :: text
    if (abs(x) < 1e7_wp .and. x == aint(x)) then
      text = format_integer(int(x))
    else
      text = format_real(x)
    end if
  end function bound_text

  !> What the declaration allows, for the reference tables.
  pure function allowed_text(d) result(text)
    type(declaration_t), intent(in) :: d
    character(len=:), allocatable :: text
    select case (d%kind)
    case (VALUE_REAL)
      text = bound_text(d%low)//' … '//bound_text(d%high)
      if (d%open_low) text = '> '//text
    case (VALUE_INTEGER)
      text = 'whole number '//bound_text(d%low)//' … '//bound_text(d%high)
    case (VALUE_LOGICAL)
      text = '`.true.`, `.false.`'
    case default
      if (len_trim(d%choices) == 0) then
        text = 'a text in quotes'
      else
        text = '`'//words_joined(trim(adjustl(d%choices)), '`, `')//'`'
      end if
    end select
  end function allowed_text

  !> The blank-separated `words` joined by `separator`: 'a b c' and '`, `'
  !> as 'a`, `b`, `c'.
  pure function words_joined(words, separator) result(text)
    character(len=*), intent(in) :: words, separator
    character(len=:), allocatable :: text
    integer :: i
    text = ''
    do i = 1, len(words)
      if (words(i:i) == ' ') then
        if (i > 1) then
          if (words(i - 1:i - 1) /= ' ') text = text//separator
        end if
      else
        text = text//words(i:i)
      end if
    end do
  end function words_joined

  !> Whether `group` is one of the blank-separated `groups`.
  pure logical function in_groups(group, groups)
    character(len=*), intent(in) :: group, groups
    in_groups = index(' '//trim(groups)//' ', ' '//trim(group)//' ') > 0
  end function in_groups
end module io_declaration
