!> Everything a reader of inputs uses, in one module: the input's text and
!> groups (io_input_text, with the --set/--unset overrides of
!> io_input_overrides), the group reader (io_group_reader, its values in
!> io_group_reader_values), the bounds of a real (io_input_bounds) and the
!> checks of values already read (io_input_checks).
module io_input
  use base_text, only: format_real, format_vector, lower
  use io_input_text, only: input_text_t, load_input_file, input_from_text, stdin_name, read_text_file, &
    check_known_groups, group_present, group_count
  use io_input_bounds, only: bounds_t, in_range, above
  use io_group_reader, only: group_reader_t, open_group, invalid, where_given, indexed_name
  use io_input_checks, only: check_finite, check_positive, check_nonnegative, check_range, check_choice, &
    mark_input_failure
  implicit none (type, external)
  private
  public :: input_text_t, load_input_file, input_from_text, stdin_name, read_text_file
  public :: check_known_groups, group_present, group_count, lower, format_real, format_vector, invalid, where_given
  public :: check_finite, check_positive, check_nonnegative, check_range, check_choice
  public :: group_reader_t, open_group, bounds_t, in_range, above, mark_input_failure, indexed_name
end module io_input
