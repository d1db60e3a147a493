!> The layout of a flying vehicle's records (rider_vehicle_flight): its
!> contacts' names (bit k-1 of a build's open mask), the full layout of
!> the coordinates every record holds, their units, a mask in words.
module rider_vehicle_layout
  use kinetostatics_recorder, only: mechanism_series_t
  implicit none (type, external)
  private
  public :: vehicle_contact_names, vehicle_units, open_words, N_FULL, full_names, LIFT, ROLL

  !> the contacts, bit k-1 of a build's open mask
  character(len=*), parameter :: vehicle_contact_names(2) = [character(len=5) :: 'rear', 'front']
  integer, parameter :: N_FULL = 6   ! u, v, phi, pitch, rear_lift, roll
  integer, parameter :: LIFT = 5, ROLL = 6
  character(len=*), parameter :: full_names(N_FULL) = [character(len=9) :: 'u', 'v', 'phi', 'pitch', 'rear_lift', &
                                                       'roll']

contains

  !> The units of the joined records' coordinates and dependents by their
  !> names: u, u2 in u_unit, v, v2 in v_unit, the angles rad, the lift m.
  subroutine vehicle_units(series, u_unit, v_unit, q_units, beta_units)
    type(mechanism_series_t), intent(in) :: series
    character(len=*), intent(in) :: u_unit, v_unit
    character(len=8), allocatable, intent(out) :: q_units(:), beta_units(:)
    integer :: k
    allocate (q_units(series%f), beta_units(series%r))
    do k = 1, series%f
      q_units(k) = unit_of(series%q_names(k))
    end do
    do k = 1, series%r
      beta_units(k) = unit_of(series%beta_names(k))
    end do
  contains
    function unit_of(name) result(unit)
      character(len=*), intent(in) :: name
      character(len=8) :: unit
      select case (trim(name))
      case ('u', 'u2')
        unit = u_unit
      case ('v', 'v2')
        unit = v_unit
      case ('rear_lift')
        unit = 'm'
      case default
        unit = 'rad'
      end select
    end function unit_of
  end subroutine vehicle_units

  !> The open contacts of a mask in words.
  pure function open_words(mask) result(words)
    integer, intent(in) :: mask
    character(len=:), allocatable :: words
    select case (mask)
    case (1)
      words = 'rear'
    case (2)
      words = 'front'
    case (3)
      words = 'both'
    case default
      words = 'none'
    end select
  end function open_words
end module rider_vehicle_layout
