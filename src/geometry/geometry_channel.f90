!> The closed-form tubes the water runs in when no slide is given (the
!> input's &channel): a straight incline, a helix or an S-bend of circular
!> section (geometry_tube), by their description. build_channel builds one
!> and checks it for folds and turns passing through each other; the
!> namelist reader (io_water_config) fills the description, a library caller
!> fills it directly.
module geometry_channel
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_text, only: format_real
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use geometry_tube, only: tube_surface_t, new_straight_tube, new_helix_tube, new_s_bend_tube
  implicit none (type, external)
  private
  public :: channel_description_t, build_channel

  !> Points checked along the tube for folds and clearance (tube_surface_t%check).
  integer, parameter :: check_points = 2000

  !> One channel; the defaults are &channel's (docs/inputs.md).
  type :: channel_description_t
    character(len=8) :: kind = 'straight'   !< 'straight', 'helix' or 's_bend'
    real(wp) :: radius = 0.5_wp             !< m, of the tube
    real(wp) :: incline_deg = 10            !< deg, straight: below the horizontal
    real(wp) :: length = 50                 !< m, straight: along the axis; s_bend: of x
    real(wp) :: helix_radius = 3            !< m, helix: of the centerline
    real(wp) :: pitch = 0.3_wp              !< m/rad, helix: descent per radian
    real(wp) :: turn_sense = 1              !< helix: +1 counter-clockwise from above, -1 clockwise
    real(wp) :: turns = 2                   !< helix
    real(wp) :: amplitude = 1.5_wp          !< m, s_bend
    real(wp) :: wavenumber = 0.4_wp         !< 1/m, s_bend
    real(wp) :: slope = 0.1_wp              !< 1, s_bend: descent per m of x
  end type channel_description_t

contains

  !> The tube of `d`, checked (no fold, no turn through another). On failure
  !> `variable` names the value at fault ('' when the tube as a whole is:
  !> a fold or turns through each other), for a reader to say where the
  !> input gave it; the message is left for the caller to place.
  subroutine build_channel(d, tube, status, variable)
    type(channel_description_t), intent(in) :: d
    type(tube_surface_t), intent(out) :: tube
    type(status_t), intent(inout) :: status
    character(len=:), allocatable, intent(out), optional :: variable
    if (present(variable)) variable = ''
    if (.not. status%ok()) return
    select case (trim(d%kind))
    case ('straight')
      tube = new_straight_tube(d%radius, d%incline_deg*pi/180, d%length, status)
    case ('helix')
      if (abs(d%turn_sense) /= 1) then
        call refuse('turn_sense', format_real(d%turn_sense), 'must be +1 or -1')
        return
      end if
      if (d%helix_radius <= d%radius) then
        call refuse('helix_radius', format_real(d%helix_radius), &
                    'must exceed the tube radius '//format_real(d%radius)//' m (else the tube folds)')
        return
      end if
      tube = new_helix_tube(d%radius, d%helix_radius, d%pitch, d%turn_sense, 2*pi*d%turns, status)
    case ('s_bend')
      tube = new_s_bend_tube(d%radius, d%amplitude, d%wavenumber, d%slope, d%length, status)
    case default
      call refuse('kind', ''''//trim(d%kind)//'''', '''straight'', ''helix'' or ''s_bend''')
      return
    end select
    if (status%ok()) call tube%check(check_points, status)

  contains

    !> `name` = `value` is refused: `allowed` says why.
    subroutine refuse(name, value, allowed)
      character(len=*), intent(in) :: name, value, allowed
      call set_status(status, STATUS_INVALID_INPUT, name//' = '//value//' is not allowed: '//allowed)
      if (present(variable)) variable = name
    end subroutine refuse
  end subroutine build_channel
end module geometry_channel
