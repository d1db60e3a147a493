!> Mass properties of the homogeneous solid a closed surface encloses: volume,
!> centre of mass and inertia tensor about it, by the divergence theorem over
!> the surface's parameter box,
!>     integral_V f dV = surface integral of F.n dA,  div F = f,
!> with n dA = sigma (r_u x r_v) du dv (sigma = +1 when r_u x r_v points out):
!>     V          from F = x e_1          (and e_2, e_3: three estimates, averaged)
!>     int x_i    from F = x_i^2/2 e_i
!>     int x_i^2  from F = x_i^3/3 e_i
!>     int x_i x_j from F = x_i^2 x_j/2 e_i  (i /= j)
!> Quadrature: Gauss-Legendre in a bounded direction, the trapezoidal rule in a
!> periodic one (spectrally accurate for smooth periodic integrands).
!> A surface is taken as closed when its vector area, surface integral of n dA,
!> vanishes to 1e-10 of its area: open patches (a paraboloid) are refused.
module geometry_solid
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_vector, only: cross
  use base_text, only: format_short
  use base_status, only: status_t, set_status, prefix_status, STATUS_INVALID_INPUT
  use geometry_surface, only: surface_t, surface_point_t
  implicit none (type, external)
  private
  public :: solid_properties_t, solid_properties

  type :: solid_properties_t
    real(wp) :: volume = 0               ! m^3
    real(wp) :: centre(3) = 0            ! m, surface coordinates
    real(wp) :: inertia(3, 3) = 0        ! m^5: per unit density, about the centre
  end type solid_properties_t

  integer, parameter :: default_nodes = 64
  real(wp), parameter :: closed_tol = 1e-10_wp

contains

  !> Properties of the solid enclosed by `surface`; sigma = +1 if r_u x r_v
  !> points out of the solid, -1 if in. nodes: quadrature points per direction.
  subroutine solid_properties(surface, sigma, props, status, nodes)
    class(surface_t), intent(in) :: surface
    real(wp), intent(in) :: sigma
    type(solid_properties_t), intent(out) :: props
    type(status_t), intent(inout) :: status
    integer, intent(in), optional :: nodes
    real(wp), allocatable :: u(:), wu(:), v(:), wv(:)
    real(wp) :: box(4), nda(3), x(3), vol(3), first(3), second(3, 3), area, vector_area(3), w
    type(surface_point_t) :: p
    integer :: n, i, j, a, b
    if (.not. status%ok()) return
    n = default_nodes
    if (present(nodes)) n = nodes
    call surface%domain(box(1), box(2), box(3), box(4))
    if (maxval(abs(box)) > 1e6_wp) then
      call set_status(status, STATUS_INVALID_INPUT, 'homogeneous solid of the '//surface%describe()// &
                      ': its parameter domain is unbounded, so it encloses no solid')
      return
    end if
    call nodes_on(box(1), box(2), surface%periodic_u(), n, u, wu)
    call nodes_on(box(3), box(4), surface%periodic_v(), n, v, wv)
    vol = 0; first = 0; second = 0; area = 0; vector_area = 0
    do j = 1, size(v)
      do i = 1, size(u)
        call surface%evaluate(u(i), v(j), 1, p, status)
        if (.not. status%ok()) then
          call prefix_status(status, 'homogeneous solid')
          return
        end if
        w = wu(i)*wv(j)
        nda = sigma*cross(p%ru, p%rv)*w
        x = p%r
        area = area + norm2(nda)
        vector_area = vector_area + nda
        vol = vol + x*nda
        first = first + x**2/2*nda
        do a = 1, 3
          second(a, a) = second(a, a) + x(a)**3/3*nda(a)
          do b = 1, 3
            if (b /= a) second(a, b) = second(a, b) + x(a)**2*x(b)/2*nda(a)
          end do
        end do
      end do
    end do
    if (norm2(vector_area) > closed_tol*area) then
      call set_status(status, STATUS_INVALID_INPUT, 'homogeneous solid of the '//surface%describe()// &
        ': the surface is not closed (vector area '//format_short(norm2(vector_area))//' of area '// &
        format_short(area)//'); give the mass, centre of mass and inertia instead')
      return
    end if
    props%volume = sum(vol)/3
    if (.not. props%volume > 0) then
      call set_status(status, STATUS_INVALID_INPUT, 'homogeneous solid of the '//surface%describe()// &
        ': the enclosed volume is not positive; the side (sigma) must point out of the solid')
      return
    end if
    ! the two estimates of each mixed moment are averaged (both exact)
    second = (second + transpose(second))/2
    props%centre = first/props%volume
    do a = 1, 3
      do b = 1, 3
        props%inertia(a, b) = -(second(a, b) - props%volume*props%centre(a)*props%centre(b))
      end do
    end do
    w = -(props%inertia(1, 1) + props%inertia(2, 2) + props%inertia(3, 3))   ! int |r - c|^2
    do a = 1, 3
      props%inertia(a, a) = props%inertia(a, a) + w
    end do
  end subroutine solid_properties

  !> Nodes and weights on [a, b]: trapezoidal (periodic) or Gauss-Legendre.
  pure subroutine nodes_on(a, b, periodic, n, x, w)
    real(wp), intent(in) :: a, b
    logical, intent(in) :: periodic
    integer, intent(in) :: n
    real(wp), allocatable, intent(out) :: x(:), w(:)
    integer :: i
    allocate (x(n), w(n))
    if (periodic) then
      do i = 1, n
        x(i) = a + (b - a)*(i - 1)/real(n, wp)
      end do
      w = (b - a)/n
    else
      call gauss_legendre(n, x, w)
      x = (a + b)/2 + (b - a)/2*x
      w = w*(b - a)/2
    end if
  end subroutine nodes_on

  !> Gauss-Legendre nodes and weights on [-1, 1] (Newton on P_n from the
  !> Chebyshev-like start cos(pi (i - 1/4)/(n + 1/2))).
  pure subroutine gauss_legendre(n, x, w)
    integer, intent(in) :: n
    real(wp), intent(out) :: x(n), w(n)
    real(wp) :: z, p0, p1, p2, dp
    integer :: i, k, it
    do i = 1, (n + 1)/2
      z = cos(pi*(i - 0.25_wp)/(n + 0.5_wp))
      do it = 1, 100
        p0 = 1
        p1 = z
        do k = 2, n
          p2 = ((2*k - 1)*z*p1 - (k - 1)*p0)/k
          p0 = p1
          p1 = p2
        end do
        if (n == 1) p0 = 1
        dp = n*(z*p1 - p0)/(z*z - 1)
        z = z - p1/dp
        if (abs(p1/dp) < 1e-16_wp) exit
      end do
      x(i) = -z
      x(n + 1 - i) = z
      w(i) = 2/((1 - z*z)*dp*dp)
      w(n + 1 - i) = w(i)
    end do
  end subroutine gauss_legendre
end module geometry_solid
