!> The surface seam: a parametrised surface r(u, v) with partial derivatives.
!>
!> Every surface (elementary, spline, placed) extends surface_t and fills one
!> evaluation record, surface_point_t, with r and its partials up to the order
!> asked for (0..3). Evaluation takes the surface intent(in) and keeps no cache.
!>
!> Charts: a parametrisation may be singular at poles (an ellipsoid's (3.57)
!> at v = +-pi/2) while the same surface has other charts that are regular
!> there. A surface with such charts says so (`has_charts`), measures how far
!> (u, v) is from its chart's poles (`chart_margin`, positive inside, zero at
!> the chart's edge), names the chart in which a point lies farthest from the
!> poles (`chart_toward`), gives itself in that chart with the rotation
!> between the two (`chart`: the chart's point r' is the surface's point
!> r = P r'), and the parameters of a point (`chart_parameters`). The
!> defaults: one chart, never changed. Elements that carry a surface change
!> charts through these alone (kinetostatics_inverse_surface_joint).
module geometry_surface
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  implicit none (type, external)
  private
  public :: surface_t, surface_point_t

  !> r(u,v) and its partial derivatives, filled up to the order asked for.
  !> Entries above `order` stay zero.
  type :: surface_point_t
    integer  :: order = 0
    real(wp) :: r(3) = 0
    real(wp) :: ru(3) = 0, rv(3) = 0
    real(wp) :: ruu(3) = 0, ruv(3) = 0, rvv(3) = 0
    real(wp) :: ruuu(3) = 0, ruuv(3) = 0, ruvv(3) = 0, rvvv(3) = 0
  end type surface_point_t

  !> A parametrised surface. Only `evaluate` is deferred; the domain and
  !> periodicity queries default to an unbounded, non-periodic surface.
  type, abstract :: surface_t
  contains
    procedure(evaluate_i), deferred :: evaluate
    procedure :: in_domain => surface_in_domain
    procedure :: domain => surface_domain
    procedure :: periodic_u => surface_periodic_u
    procedure :: periodic_v => surface_periodic_v
    procedure :: describe => surface_describe
    procedure :: parameter_units => surface_parameter_units
    !> r(u_i, v_j) on a grid (x, y, z of shape (size(v), size(u))); a surface
    !> may override it with a faster way than point by point.
    procedure :: points_on_grid => surface_points_on_grid
    !> r(u, v) = r(0, 0) + u r_u + v r_v with constant r_u, r_v (a plane):
    !> its Darboux frame never turns (kinetostatics_plane_joint; default: no)
    procedure :: affine => surface_affine
    !> charts (module comment); the defaults: one chart, never changed
    procedure :: has_charts => surface_has_charts
    procedure :: chart_margin => surface_chart_margin
    procedure :: chart_toward => surface_chart_toward
    procedure :: chart => surface_chart
    procedure :: chart_parameters => surface_chart_parameters
  end type surface_t

  abstract interface
    !> Fills p with r and its partials up to `order` (0..3) at (u, v).
    pure subroutine evaluate_i(self, u, v, order, p, status)
      import :: surface_t, surface_point_t, status_t, wp
      class(surface_t), intent(in) :: self
      real(wp), intent(in) :: u, v
      integer, intent(in) :: order          ! 0..3
      type(surface_point_t), intent(out) :: p
      type(status_t), intent(out) :: status
    end subroutine evaluate_i
  end interface

contains

  !> Whether (u, v) lies in the parameter domain (default: inside the box of
  !> `domain`, any value in a periodic direction).
  pure logical function surface_in_domain(self, u, v) result(inside)
    class(surface_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    real(wp) :: u_min, u_max, v_min, v_max
    call self%domain(u_min, u_max, v_min, v_max)
    inside = (self%periodic_u() .or. (u >= u_min .and. u <= u_max)) .and. &
             (self%periodic_v() .or. (v >= v_min .and. v <= v_max))
  end function surface_in_domain

  !> The parameter box (default: unbounded, +-huge).
  pure subroutine surface_domain(self, u_min, u_max, v_min, v_max)
    class(surface_t), intent(in) :: self
    real(wp), intent(out) :: u_min, u_max, v_min, v_max
    associate (unused => self)   ! the default ignores the surface
    end associate
    u_min = -huge(1.0_wp); u_max = huge(1.0_wp)
    v_min = -huge(1.0_wp); v_max = huge(1.0_wp)
  end subroutine surface_domain

  !> Whether r is periodic in u over [u_min, u_max] (default: no).
  pure logical function surface_periodic_u(self) result(periodic)
    class(surface_t), intent(in) :: self
    associate (unused => self)   ! the default ignores the surface
    end associate
    periodic = .false.
  end function surface_periodic_u

  !> Whether r is periodic in v over [v_min, v_max] (default: no).
  pure logical function surface_periodic_v(self) result(periodic)
    class(surface_t), intent(in) :: self
    associate (unused => self)   ! the default ignores the surface
    end associate
    periodic = .false.
  end function surface_periodic_v

  !> A short human-readable name of the surface.
  pure subroutine surface_points_on_grid(self, u, v, x, y, z, status)
    class(surface_t), intent(in) :: self
    real(wp), intent(in) :: u(:), v(:)
    real(wp), intent(out) :: x(:, :), y(:, :), z(:, :)   ! (size(v), size(u)), m
    type(status_t), intent(out) :: status
    type(surface_point_t) :: p
    integer :: i, j
    status%code = 0
    do i = 1, size(u)
      do j = 1, size(v)
        call self%evaluate(u(i), v(j), 0, p, status)
        if (.not. status%ok()) return
        x(j, i) = p%r(1); y(j, i) = p%r(2); z(j, i) = p%r(3)
      end do
    end do
  end subroutine surface_points_on_grid

  pure function surface_describe(self) result(text)
    class(surface_t), intent(in) :: self
    character(len=:), allocatable :: text
    associate (unused => self)   ! the default ignores the surface
    end associate
    text = 'surface'
  end function surface_describe

  !> The units of u and v (UDUNITS/pint text: 'm', 'rad', '1'), for result
  !> files; the default is a dimensionless parameter.
  pure subroutine surface_parameter_units(self, u_units, v_units)
    class(surface_t), intent(in) :: self
    character(len=:), allocatable, intent(out) :: u_units, v_units
    associate (unused => self)   ! the default ignores the surface
    end associate
    u_units = '1'; v_units = '1'
  end subroutine surface_parameter_units

  pure logical function surface_affine(self) result(affine)
    class(surface_t), intent(in) :: self
    associate (unused => self)   ! the default ignores the surface
    end associate
    affine = .false.
  end function surface_affine

  !> Whether the surface has charts other than its own (default: no).
  pure logical function surface_has_charts(self) result(has)
    class(surface_t), intent(in) :: self
    associate (unused => self)   ! the default ignores the surface
    end associate
    has = .false.
  end function surface_has_charts

  !> How far v is from the chart's poles: positive inside the chart, zero at
  !> its edge, where the chart must change (default: 1, no edge).
  pure real(wp) function surface_chart_margin(self, v) result(margin)
    class(surface_t), intent(in) :: self
    real(wp), intent(in) :: v
    associate (unused => self, unused_v => v)   ! the default ignores the surface
    end associate
    margin = 1
  end function surface_chart_margin

  !> The chart in which the point r (the surface's own coordinates) lies
  !> farthest from the poles (default: 0, the only chart).
  pure integer function surface_chart_toward(self, r) result(k)
    class(surface_t), intent(in) :: self
    real(wp), intent(in) :: r(3)
    associate (unused => self, unused_r => r)   ! the default ignores the surface
    end associate
    k = 0
  end function surface_chart_toward

  !> The surface in chart k: chart_surface, whose point r' is the surface's
  !> point r = p r' (default: the surface itself, p the identity).
  pure subroutine surface_chart(self, k, chart_surface, p)
    class(surface_t), intent(in) :: self
    integer, intent(in) :: k
    class(surface_t), allocatable, intent(inout) :: chart_surface   ! replaced (pure: not intent(out))
    real(wp), intent(out) :: p(3, 3)
    associate (unused_k => k)   ! one chart
    end associate
    if (allocated(chart_surface)) deallocate (chart_surface)
    allocate (chart_surface, source=self)
    p = reshape([1, 0, 0, 0, 1, 0, 0, 0, 1], [3, 3])
  end subroutine surface_chart

  !> The parameters (u, v) of the point r of the surface (its own
  !> coordinates); the default has no inverse and says so.
  pure subroutine surface_chart_parameters(self, r, u, v, status)
    class(surface_t), intent(in) :: self
    real(wp), intent(in) :: r(3)
    real(wp), intent(out) :: u, v
    type(status_t), intent(out) :: status
    associate (unused_r => r)
    end associate
    u = 0
    v = 0
    call set_status(status, STATUS_INVALID_INPUT, 'the '//self%describe()//' has no parameters of a point '// &
                    '(only a surface with charts has)')
  end subroutine surface_chart_parameters
end module geometry_surface
