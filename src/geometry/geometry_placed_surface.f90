!> A surface placed in space: r(u, v) = origin + R r_base(u, v).
!>
!> Wraps any surface (it owns a copy in an allocatable component); every
!> partial derivative is rotated by R, the domain and periodicity are the
!> base surface's, and so are its charts (geometry_surface), placed alike:
!> the base's chart k, r_b = P_b r', is the placed surface's r = P r'' with
!> P = R P_b R^T and the chart surface r'' = P^T origin + R r' (a placed
!> surface too), so a turned ellipsoid changes charts as the ellipsoid.
module geometry_placed_surface
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, prefix_status, STATUS_INVALID_INPUT
  use base_vector, only: rotation_xyz, identity3
  use geometry_surface, only: surface_t, surface_point_t
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  implicit none (type, external)
  private
  public :: placed_surface_t

  type, extends(surface_t) :: placed_surface_t
    private
    class(surface_t), allocatable :: base
    real(wp) :: origin(3) = 0           ! m, where the base's origin goes
    real(wp) :: rotation(3, 3) = reshape([1, 0, 0, 0, 1, 0, 0, 0, 1], [3, 3])  ! base -> world
  contains
    procedure :: evaluate => placed_evaluate
    procedure :: in_domain => placed_in_domain
    procedure :: domain => placed_domain
    procedure :: periodic_u => placed_periodic_u
    procedure :: periodic_v => placed_periodic_v
    procedure :: describe => placed_describe
    procedure :: parameter_units => placed_parameter_units
    procedure :: has_charts => placed_has_charts
    procedure :: chart_margin => placed_chart_margin
    procedure :: chart_toward => placed_chart_toward
    procedure :: chart => placed_chart
    procedure :: chart_parameters => placed_chart_parameters
    procedure :: origin_of => placed_origin
    procedure :: rotation_of => placed_rotation
  end type placed_surface_t

  !> placed_surface_t(base, origin, status, angles=, rotation=): orientation
  !> from Cardan angles (rad, R = Rx Ry Rz, base_vector::rotation_xyz) or a
  !> given proper rotation matrix; neither means no rotation.
  interface placed_surface_t
    module procedure new_placed_surface
  end interface placed_surface_t

  !> Allowed deviation of a given rotation from orthonormality, max |R^T R - I|,
  !> and of its determinant from +1 (matrices typed with ~15 digits pass).
  real(wp), parameter :: rotation_tol = 1e-10_wp

contains

  function new_placed_surface(base, origin, status, angles, rotation) result(s)
    class(surface_t), intent(in) :: base
    real(wp), intent(in) :: origin(3)             ! m
    type(status_t), intent(out) :: status
    real(wp), intent(in), optional :: angles(3)   ! rad, Cardan x-y'-z''
    real(wp), intent(in), optional :: rotation(3, 3)
    type(placed_surface_t) :: s
    real(wp) :: r(3, 3), det
    character(len=30) :: buffer
    if (.not. all(ieee_is_finite(origin))) then
      call set_status(status, STATUS_INVALID_INPUT, 'origin is not finite')
    else if (present(angles) .and. present(rotation)) then
      call set_status(status, STATUS_INVALID_INPUT, 'give either angles or a rotation matrix, not both')
    else if (present(angles)) then
      if (.not. all(ieee_is_finite(angles))) then
        call set_status(status, STATUS_INVALID_INPUT, 'rotation angles are not finite')
      else
        r = rotation_xyz(angles)
      end if
    else if (present(rotation)) then
      r = rotation
      if (.not. all(ieee_is_finite(rotation))) then
        call set_status(status, STATUS_INVALID_INPUT, 'rotation matrix is not finite')
      else
        det = r(1, 1)*(r(2, 2)*r(3, 3) - r(3, 2)*r(2, 3)) - r(1, 2)*(r(2, 1)*r(3, 3) - r(3, 1)*r(2, 3)) &
              + r(1, 3)*(r(2, 1)*r(3, 2) - r(3, 1)*r(2, 2))
        if (maxval(abs(matmul(transpose(r), r) - identity3())) > rotation_tol .or. &
            abs(det - 1) > rotation_tol) then
          write (buffer, '(es12.4)') det
          call set_status(status, STATUS_INVALID_INPUT, 'rotation matrix is not a proper rotation ' // &
                          '(R^T R /= I or det R = ' // trim(adjustl(buffer)) // ' /= 1)')
        end if
      end if
    else
      r = identity3()
    end if
    if (.not. status%ok()) then
      call prefix_status(status, 'placed surface')
      return
    end if
    allocate (s%base, source=base)
    s%origin = origin
    s%rotation = r
  end function new_placed_surface

  pure subroutine placed_evaluate(self, u, v, order, p, status)
    class(placed_surface_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    integer, intent(in) :: order
    type(surface_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    type(surface_point_t) :: q
    if (.not. allocated(self%base)) then
      call set_status(status, STATUS_INVALID_INPUT, 'placed surface: not constructed (no base surface)')
      return
    end if
    call self%base%evaluate(u, v, order, q, status)
    if (.not. status%ok()) return
    associate (r => self%rotation)
      p%order = q%order
      p%r = self%origin + matmul(r, q%r)
      if (order >= 1) then
        p%ru = matmul(r, q%ru)
        p%rv = matmul(r, q%rv)
      end if
      if (order >= 2) then
        p%ruu = matmul(r, q%ruu)
        p%ruv = matmul(r, q%ruv)
        p%rvv = matmul(r, q%rvv)
      end if
      if (order >= 3) then
        p%ruuu = matmul(r, q%ruuu)
        p%ruuv = matmul(r, q%ruuv)
        p%ruvv = matmul(r, q%ruvv)
        p%rvvv = matmul(r, q%rvvv)
      end if
    end associate
  end subroutine placed_evaluate

  pure logical function placed_in_domain(self, u, v) result(inside)
    class(placed_surface_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    inside = .false.
    if (allocated(self%base)) inside = self%base%in_domain(u, v)
  end function placed_in_domain

  pure subroutine placed_domain(self, u_min, u_max, v_min, v_max)
    class(placed_surface_t), intent(in) :: self
    real(wp), intent(out) :: u_min, u_max, v_min, v_max
    u_min = 0; u_max = 0; v_min = 0; v_max = 0
    if (allocated(self%base)) call self%base%domain(u_min, u_max, v_min, v_max)
  end subroutine placed_domain

  pure logical function placed_periodic_u(self) result(periodic)
    class(placed_surface_t), intent(in) :: self
    periodic = .false.
    if (allocated(self%base)) periodic = self%base%periodic_u()
  end function placed_periodic_u

  pure logical function placed_periodic_v(self) result(periodic)
    class(placed_surface_t), intent(in) :: self
    periodic = .false.
    if (allocated(self%base)) periodic = self%base%periodic_v()
  end function placed_periodic_v

  pure function placed_describe(self) result(text)
    class(placed_surface_t), intent(in) :: self
    character(len=:), allocatable :: text
    if (allocated(self%base)) then
      text = 'placed ' // self%base%describe()
    else
      text = 'placed surface (empty)'
    end if
  end function placed_describe

  !> Where the base surface's origin lies (m).
  pure function placed_origin(self) result(origin)
    class(placed_surface_t), intent(in) :: self
    real(wp) :: origin(3)
    origin = self%origin
  end function placed_origin

  !> The rotation from base-surface to world coordinates.
  pure function placed_rotation(self) result(rotation)
    class(placed_surface_t), intent(in) :: self
    real(wp) :: rotation(3, 3)
    rotation = self%rotation
  end function placed_rotation

  !> The base's charts (module comment).
  pure logical function placed_has_charts(self) result(has)
    class(placed_surface_t), intent(in) :: self
    has = .false.
    if (allocated(self%base)) has = self%base%has_charts()
  end function placed_has_charts

  pure real(wp) function placed_chart_margin(self, v) result(margin)
    class(placed_surface_t), intent(in) :: self
    real(wp), intent(in) :: v
    margin = self%base%chart_margin(v)
  end function placed_chart_margin

  pure integer function placed_chart_toward(self, r) result(k)
    class(placed_surface_t), intent(in) :: self
    real(wp), intent(in) :: r(3)
    k = self%base%chart_toward(matmul(transpose(self%rotation), r - self%origin))
  end function placed_chart_toward

  pure subroutine placed_chart(self, k, chart_surface, p)
    class(placed_surface_t), intent(in) :: self
    integer, intent(in) :: k
    class(surface_t), allocatable, intent(inout) :: chart_surface   ! replaced (pure: not intent(out))
    real(wp), intent(out) :: p(3, 3)
    type(placed_surface_t) :: placed
    real(wp) :: p_base(3, 3)
    call self%base%chart(k, placed%base, p_base)
    p = matmul(self%rotation, matmul(p_base, transpose(self%rotation)))
    placed%origin = matmul(transpose(p), self%origin)
    placed%rotation = self%rotation
    if (allocated(chart_surface)) deallocate (chart_surface)
    allocate (chart_surface, source=placed)
  end subroutine placed_chart

  pure subroutine placed_chart_parameters(self, r, u, v, status)
    class(placed_surface_t), intent(in) :: self
    real(wp), intent(in) :: r(3)
    real(wp), intent(out) :: u, v
    type(status_t), intent(out) :: status
    call self%base%chart_parameters(matmul(transpose(self%rotation), r - self%origin), u, v, status)
  end subroutine placed_chart_parameters

  pure subroutine placed_parameter_units(self, u_units, v_units)
    class(placed_surface_t), intent(in) :: self
    character(len=:), allocatable, intent(out) :: u_units, v_units
    call self%base%parameter_units(u_units, v_units)
  end subroutine placed_parameter_units
end module geometry_placed_surface
