!> Checks of input values already read (for values a reader cannot check
!> alone), with the reader's message; and the rule that a model that cannot
!> be built from its input is bad input.
module io_input_checks
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use base_kinds, only: wp
  use base_status, only: status_t, STATUS_IO, STATUS_INVALID_INPUT
  use base_text, only: format_real, lower
  use io_input_text, only: input_text_t
  use io_input_bounds, only: bounds_t, in_range, above
  use io_group_reader, only: invalid
  implicit none (type, external)
  private
  public :: check_finite, check_positive, check_nonnegative, check_range, check_choice, mark_input_failure

contains

  !> A model that cannot be built from the input is bad input (exit status 1,
  !> nothing written), whatever the builder's code, unless a file could not be read.
  pure subroutine mark_input_failure(status)
    type(status_t), intent(inout) :: status
    if (.not. status%ok() .and. status%code /= STATUS_IO) status%code = STATUS_INVALID_INPUT
  end subroutine mark_input_failure

  subroutine check_finite(input, group, variable, value, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group, variable
    real(wp), intent(in) :: value
    type(status_t), intent(inout) :: status
    if (.not. status%ok()) return
    if (.not. ieee_is_finite(value)) &
      call invalid(input, group, variable, format_real(value), 'must be a finite number', status)
  end subroutine check_finite

  !> value > 0 and finite; `unit` is shown in the message.
  subroutine check_positive(input, group, variable, value, unit, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group, variable, unit
    real(wp), intent(in) :: value
    type(status_t), intent(inout) :: status
    call check_bounds(input, group, variable, value, above(0.0_wp, huge(1.0_wp), unit), &
                      'must be a finite number > 0 ('//unit//')', status)
  end subroutine check_positive

  subroutine check_nonnegative(input, group, variable, value, unit, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group, variable, unit
    real(wp), intent(in) :: value
    type(status_t), intent(inout) :: status
    call check_bounds(input, group, variable, value, in_range(0.0_wp, huge(1.0_wp), unit), &
                      'must be a finite number >= 0 ('//unit//')', status)
  end subroutine check_nonnegative

  subroutine check_range(input, group, variable, value, low, high, unit, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group, variable, unit
    real(wp), intent(in) :: value, low, high
    type(status_t), intent(inout) :: status
    type(bounds_t) :: b
    b = in_range(low, high, unit)
    call check_bounds(input, group, variable, value, b, b%text(), status)
  end subroutine check_range

  !> value within `b`, else the reader's message with `allowed`.
  subroutine check_bounds(input, group, variable, value, b, allowed, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group, variable, allowed
    real(wp), intent(in) :: value
    type(bounds_t), intent(in) :: b
    type(status_t), intent(inout) :: status
    if (.not. status%ok()) return
    if (.not. b%allows(value)) call invalid(input, group, variable, format_real(value), allowed, status)
  end subroutine check_bounds

  !> A keyword among `choices` (compared in lower case, trailing blanks ignored).
  subroutine check_choice(input, group, variable, value, choices, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group, variable, value
    character(len=*), intent(in) :: choices(:)
    type(status_t), intent(inout) :: status
    integer :: j
    character(len=:), allocatable :: list
    if (.not. status%ok()) return
    if (any(choices == lower(trim(adjustl(value))))) return
    list = ''
    do j = 1, size(choices)
      list = list//' '//trim(choices(j))
    end do
    call invalid(input, group, variable, "'"//trim(value)//"'", 'must be one of'//list, status)
  end subroutine check_choice
end module io_input_checks
