!> Surfaces of revolution about the z axis from a profile (rho(v), z(v)) in
!> the (rho, z) half-plane:
!>
!>     r(u, v) = [rho(v) cos u, rho(v) sin u, z(v)],   u in [0, 2 pi) periodic,
!>
!> with every partial to third order from the profile's derivatives
!> (r_u = [-rho sin u, rho cos u, 0], r_v = [rho' cos u, rho' sin u, z'], ...).
!> The profile is
!>   a cone          rho = v tan(alpha), z = v: v the height above the apex (m),
!>                   alpha the half-angle from the axis (a funnel, a conical bowl);
!>   a sphere zone   rho = R cos v, z = R sin v: v the latitude (rad), a
!>                   spherical bowl (v < 0) or dome;
!>   points          (rho_i, z_i) interpolated by a parametric spline
!>                   (numerics_spline_curve: quintic from 6 points, cubic from
!>                   4), v the chord length along the points (m).
!> r_u x r_v = rho [z' cos u, z' sin u, -rho']: away from the axis where the
!> profile rises outward (a bowl's outside; its inside is side = -1).
!>
!> The axis is a pole (rho = 0: r_u = 0, no normal from r_u x r_v, and no
!> chart of this parametrisation is regular there). Rather than chart it, a
!> profile that reaches or crosses the axis is refused when the surface is
!> built: the message says where and to end the profile off the axis (a bowl
!> with a flat or rounded bottom is a profile that ends at a small rho, or
!> another shape in the input). The domain in v is the profile's; its ends
!> are edges like a slide's.
module geometry_revolution
  use base_kinds, only: wp
  use base_constants, only: pi, two_pi, half_pi
  use base_text, only: format_short
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use base_spec, only: spec_t, declare
  use numerics_spline_curve, only: spline_curve_t
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_surface_kind, only: surface_kind_t
  use geometry_elementary_kinds, only: semi_axis
  implicit none (type, external)
  private
  public :: revolution_t, new_cone, new_sphere_zone, new_profile_revolution
  public :: cone_kind, sphere_zone_kind, revolution_kind

  integer, parameter :: PROFILE_CONE = 1, PROFILE_SPHERE_ZONE = 2, PROFILE_POINTS = 3
  !> Samples per spline span at which a point profile is checked to stay off the axis.
  integer, parameter :: samples_per_span = 20

  type, extends(surface_t) :: revolution_t
    private
    integer :: profile = PROFILE_CONE
    real(wp) :: tan_alpha = 1          ! cone
    real(wp) :: radius = 1             ! m, sphere zone
    type(spline_curve_t) :: spline     ! points: (rho, z) over the chord length
    real(wp) :: v_min = 0, v_max = 1
  contains
    procedure :: evaluate => revolution_evaluate
    procedure :: domain => revolution_domain
    procedure :: periodic_u => revolution_periodic_u
    procedure :: describe => revolution_describe
    procedure :: parameter_units => revolution_parameter_units
  end type revolution_t

contains

  !> The cone of half-angle alpha (rad, from the axis) with its apex at the
  !> origin, opening upward, between the heights z_min and z_max (m) above
  !> the apex: 0 < z_min < z_max (the apex is the axis).
  function new_cone(alpha, z_min, z_max, status) result(s)
    real(wp), intent(in) :: alpha, z_min, z_max
    type(status_t), intent(out) :: status
    type(revolution_t) :: s
    if (.not. (alpha > 0 .and. alpha < half_pi)) then
      call set_status(status, STATUS_INVALID_INPUT, 'cone: half-angle '//format_short(alpha*180/pi)// &
                      ' degrees; it must lie strictly between 0 and 90')
    else if (.not. (z_min > 0)) then
      call set_status(status, STATUS_INVALID_INPUT, 'cone: z_min = '//format_short(z_min)//' m reaches the '// &
                      'apex, a pole of the surface of revolution (no chart there): give z_min > 0')
    else if (.not. (z_max > z_min)) then
      call set_status(status, STATUS_INVALID_INPUT, 'cone: z_max = '//format_short(z_max)//' m must exceed '// &
                      'z_min = '//format_short(z_min)//' m')
    end if
    s%profile = PROFILE_CONE
    s%tan_alpha = tan(alpha)
    s%v_min = z_min
    s%v_max = z_max
  end function new_cone

  !> The zone of the sphere of radius R (m) about the origin between the
  !> latitudes v_min < v_max (rad), strictly inside (-pi/2, pi/2) (the poles
  !> are on the axis).
  function new_sphere_zone(radius, v_min, v_max, status) result(s)
    real(wp), intent(in) :: radius, v_min, v_max
    type(status_t), intent(out) :: status
    type(revolution_t) :: s
    if (.not. (radius > 0)) then
      call set_status(status, STATUS_INVALID_INPUT, 'sphere zone: radius = '//format_short(radius)// &
                      ' m; it must be > 0')
    else if (.not. (v_min > -half_pi .and. v_max < half_pi)) then
      call set_status(status, STATUS_INVALID_INPUT, 'sphere zone: the latitudes '//format_short(v_min*180/pi)// &
                      ' .. '//format_short(v_max*180/pi)//' degrees reach a pole on the axis (no chart there): '// &
                      'keep them strictly between -90 and 90')
    else if (.not. (v_max > v_min)) then
      call set_status(status, STATUS_INVALID_INPUT, 'sphere zone: latitude_max must exceed latitude_min')
    end if
    s%profile = PROFILE_SPHERE_ZONE
    s%radius = radius
    s%v_min = v_min
    s%v_max = v_max
  end function new_sphere_zone

  !> The profile through the points (rho_i, z_i) (m), interpolated (quintic
  !> from 6 points, cubic from 4) over their chord length; every rho_i and
  !> the spline between them must stay > 0 (off the axis).
  function new_profile_revolution(rho, z, status) result(s)
    real(wp), intent(in) :: rho(:), z(:)
    type(status_t), intent(out) :: status
    type(revolution_t) :: s
    real(wp), allocatable :: chord(:)
    real(wp) :: d(2, 0:3), v
    integer :: i, m
    m = size(rho)
    s%profile = PROFILE_POINTS
    if (size(z) /= m) then
      call set_status(status, STATUS_INVALID_INPUT, 'profile: '//format_short(real(m, wp))//' values of rho '// &
                      'but '//format_short(real(size(z), wp))//' of z; give one z per rho')
      return
    end if
    if (m < 4) then
      call set_status(status, STATUS_INVALID_INPUT, 'profile: '//format_short(real(m, wp))//' points; a '// &
                      'spline profile needs at least 4 (6 for a quintic)')
      return
    end if
    if (any(.not. rho > 0)) then
      i = findloc(rho > 0, .false., dim=1)
      call set_status(status, STATUS_INVALID_INPUT, 'profile: point '//format_short(real(i, wp))//' has rho = '// &
                      format_short(rho(i))//' m: the axis (rho = 0) is a pole of the surface of revolution (no '// &
                      'chart there); end the profile off the axis (rho > 0)')
      return
    end if
    allocate (chord(m))
    chord(1) = 0
    do i = 2, m
      chord(i) = chord(i - 1) + norm2([rho(i) - rho(i - 1), z(i) - z(i - 1)])
      if (.not. chord(i) > chord(i - 1)) then
        call set_status(status, STATUS_INVALID_INPUT, 'profile: points '//format_short(real(i - 1, wp))// &
                        ' and '//format_short(real(i, wp))//' coincide')
        return
      end if
    end do
    call s%spline%fit(reshape([(([rho(i), z(i)]), i = 1, m)], [2, m]), 0.0_wp, merge(5, 3, m >= 6), status, &
                      parameters=chord)
    if (.not. status%ok()) return
    s%v_min = 0
    s%v_max = chord(m)
    do i = 0, samples_per_span*(m - 1)
      v = s%v_max*i/real(samples_per_span*(m - 1), wp)
      call s%spline%evaluate(v, d, 0)
      if (.not. d(1, 0) > 0) then
        call set_status(status, STATUS_INVALID_INPUT, 'profile: the spline through the points reaches the axis '// &
                        '(rho = '//format_short(d(1, 0))//' m at z = '//format_short(d(2, 0))//' m), a pole of '// &
                        'the surface of revolution (no chart there); keep the points farther from the axis')
        return
      end if
    end do
  end function new_profile_revolution

  !> rho, z and their derivatives up to `order` at v: d(1, j) = rho^(j), d(2, j) = z^(j).
  pure subroutine profile_at(self, v, order, d)
    class(revolution_t), intent(in) :: self
    real(wp), intent(in) :: v
    integer, intent(in) :: order
    real(wp), intent(out) :: d(2, 0:3)
    d = 0
    select case (self%profile)
    case (PROFILE_CONE)
      d(:, 0) = [v*self%tan_alpha, v]
      d(:, 1) = [self%tan_alpha, 1.0_wp]
    case (PROFILE_SPHERE_ZONE)
      d(:, 0) = self%radius*[cos(v), sin(v)]
      d(:, 1) = self%radius*[-sin(v), cos(v)]
      d(:, 2) = -d(:, 0)
      d(:, 3) = -d(:, 1)
    case default
      call self%spline%evaluate(v, d, order)
    end select
  end subroutine profile_at

  pure subroutine revolution_evaluate(self, u, v, order, p, status)
    class(revolution_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    integer, intent(in) :: order
    type(surface_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    real(wp) :: d(2, 0:3), c, s
    if (order < 0 .or. order > 3) then
      call set_status(status, STATUS_INVALID_INPUT, 'surface of revolution: derivative order must be 0..3')
      return
    end if
    p%order = order
    call profile_at(self, v, order, d)
    c = cos(u)
    s = sin(u)
    p%r = [d(1, 0)*c, d(1, 0)*s, d(2, 0)]
    if (order >= 1) then
      p%ru = [-d(1, 0)*s, d(1, 0)*c, 0.0_wp]
      p%rv = [d(1, 1)*c, d(1, 1)*s, d(2, 1)]
    end if
    if (order >= 2) then
      p%ruu = [-d(1, 0)*c, -d(1, 0)*s, 0.0_wp]
      p%ruv = [-d(1, 1)*s, d(1, 1)*c, 0.0_wp]
      p%rvv = [d(1, 2)*c, d(1, 2)*s, d(2, 2)]
    end if
    if (order >= 3) then
      p%ruuu = [d(1, 0)*s, -d(1, 0)*c, 0.0_wp]
      p%ruuv = [-d(1, 1)*c, -d(1, 1)*s, 0.0_wp]
      p%ruvv = [-d(1, 2)*s, d(1, 2)*c, 0.0_wp]
      p%rvvv = [d(1, 3)*c, d(1, 3)*s, d(2, 3)]
    end if
  end subroutine revolution_evaluate

  pure subroutine revolution_domain(self, u_min, u_max, v_min, v_max)
    class(revolution_t), intent(in) :: self
    real(wp), intent(out) :: u_min, u_max, v_min, v_max
    u_min = 0
    u_max = two_pi
    v_min = self%v_min
    v_max = self%v_max
  end subroutine revolution_domain

  pure logical function revolution_periodic_u(self) result(periodic)
    class(revolution_t), intent(in) :: self
    associate (unused => self)   ! every surface of revolution turns all round
    end associate
    periodic = .true.
  end function revolution_periodic_u

  pure function revolution_describe(self) result(text)
    class(revolution_t), intent(in) :: self
    character(len=:), allocatable :: text
    select case (self%profile)
    case (PROFILE_CONE)
      text = 'cone half-angle = '//format_short(atan(self%tan_alpha)*180/pi)//' degrees, z = '// &
             format_short(self%v_min)//' .. '//format_short(self%v_max)//' m'
    case (PROFILE_SPHERE_ZONE)
      text = 'sphere zone radius = '//format_short(self%radius)//' m, latitude '// &
             format_short(self%v_min*180/pi)//' .. '//format_short(self%v_max*180/pi)//' degrees'
    case default
      text = 'surface of revolution of a profile '//format_short(self%v_max)//' m long'
    end select
  end function revolution_describe

  pure subroutine revolution_parameter_units(self, u_units, v_units)
    class(revolution_t), intent(in) :: self
    character(len=:), allocatable, intent(out) :: u_units, v_units
    u_units = 'rad'
    v_units = 'm'
    if (self%profile == PROFILE_SPHERE_ZONE) v_units = 'rad'
  end subroutine revolution_parameter_units

  ! ------------------------------------------------------ the kinds inputs name

  function cone_kind() result(kind)
    type(surface_kind_t) :: kind
    kind%name = 'cone'
    kind%meaning = 'the cone about z, apex at the origin, opening upward (u the turn, v = z)'
    kind%parameters = [declare('half_angle_deg', 'deg', 0.0_wp, 89.9_wp, 'half-angle from the axis', &
                               open_low=.true.), &
                       declare('z_min', 'm', 0.0_wp, 1e4_wp, 'lowest height above the apex', open_low=.true.), &
                       declare('z_max', 'm', 0.0_wp, 1e4_wp, 'highest height above the apex', open_low=.true.)]
    kind%build => build_cone
  end function cone_kind

  subroutine build_cone(spec, surface, status)
    type(spec_t), intent(in) :: spec
    class(surface_t), allocatable, intent(out) :: surface
    type(status_t), intent(inout) :: status
    allocate (surface, source=new_cone(spec%value('half_angle_deg')*pi/180, spec%value('z_min'), &
                                       spec%value('z_max'), status))
  end subroutine build_cone

  function sphere_zone_kind() result(kind)
    type(surface_kind_t) :: kind
    kind%name = 'sphere_zone'
    kind%meaning = 'the zone of a sphere about the origin between two latitudes (u the turn, v the latitude)'
    kind%parameters = [semi_axis('radius', 'radius', required=.true.), &
                       declare('latitude_min_deg', 'deg', -89.9_wp, 89.9_wp, 'lowest latitude'), &
                       declare('latitude_max_deg', 'deg', -89.9_wp, 89.9_wp, 'highest latitude')]
    kind%build => build_sphere_zone
  end function sphere_zone_kind

  subroutine build_sphere_zone(spec, surface, status)
    type(spec_t), intent(in) :: spec
    class(surface_t), allocatable, intent(out) :: surface
    type(status_t), intent(inout) :: status
    allocate (surface, source=new_sphere_zone(spec%value('radius'), spec%value('latitude_min_deg')*pi/180, &
                                              spec%value('latitude_max_deg')*pi/180, status))
  end subroutine build_sphere_zone

  function revolution_kind() result(kind)
    type(surface_kind_t) :: kind
    kind%name = 'revolution'
    kind%meaning = 'the surface of revolution about z of a profile through points (rho_i, z_i)'
    kind%parameters = [declare('profile_rho', 'm', 0.0_wp, 1e4_wp, 'distances from the axis', count=0, &
                               open_low=.true.), &
                       declare('profile_z', 'm', -1e4_wp, 1e4_wp, 'heights', count=0)]
    kind%build => build_revolution
  end function revolution_kind

  subroutine build_revolution(spec, surface, status)
    type(spec_t), intent(in) :: spec
    class(surface_t), allocatable, intent(out) :: surface
    type(status_t), intent(inout) :: status
    allocate (surface, source=new_profile_revolution(spec%vector('profile_rho'), spec%vector('profile_z'), status))
  end subroutine build_revolution
end module geometry_revolution
