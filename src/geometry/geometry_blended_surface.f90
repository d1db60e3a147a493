!> Blended surfaces (thesis 3.5.2.4, 3.73-3.79, appendix D): n surface patches
!> joined along u with logistic weights.
!>
!> Patch j (1-based here) is used on [u_min(j), u_max(j)] x [v_min(j), v_max(j)]
!> of its own parameters; consecutive patches are separated by transitions of
!> length t(j) (u_{j-1,j} in the thesis). The blended surface has
!> u in [0, sum of patch lengths + sum of t] and v in [0, 1], and
!>   u_j = u - start(j) + u_min(j),  v_j = (v_max(j) - v_min(j)) v + v_min(j),
!> with start(1) = 0, start(j) = start(j-1) + u_max(j-1) - u_min(j-1) + t(j-1).
!> This is (3.77) with its sum written so that u_j = u_min(j) where patch j
!> starts (the printed sum pairs u_{q-1,q} with the length of patch q instead
!> of patch q-1; the thesis's examples only work with the form used here).
!> Each patch must be defined on the extended range the transitions need.
!> The weights are those of (3.79) (geometry_cross_section::blend_weights);
!> the derivatives (D.3-D.11) follow by Leibniz' rule, with the chain-rule
!> factors (v_max - v_min)^k of appendix D. A patch can be used with its
!> parameters swapped (fig. 3.16: the second cylinder).
!> Patches whose weight and weight derivatives are all below 1e-18 are not
!> evaluated (their contribution is below rounding of O(1) coordinates).
module geometry_blended_surface
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_cross_section, only: logistic, logistic_rate, blend_weights
  implicit none (type, external)
  private
  public :: blended_surface_t, blend_patch_t, new_blended_surface

  type :: blend_patch_t
    class(surface_t), allocatable :: surface
    real(wp) :: u_min = 0, u_max = 1, v_min = 0, v_max = 1
    logical :: swap_uv = .false.     ! evaluate the patch at (v_j, u_j)
  end type blend_patch_t

  type, extends(surface_t) :: blended_surface_t
    type(blend_patch_t), allocatable :: patches(:)
    real(wp), allocatable :: start(:)      ! u where each patch's own range starts
    real(wp), allocatable :: midpoint(:), rate(:)
    real(wp) :: u_end = 0
  contains
    procedure :: evaluate => blended_evaluate
    procedure :: domain => blended_domain
    procedure :: describe => blended_describe
    procedure :: parameter_units => blended_parameter_units
    procedure :: weights => blended_weights
  end type blended_surface_t

  integer, parameter :: max_patches = 16
  real(wp), parameter :: skip_weight = 1e-18_wp
  integer, parameter :: binom(0:3, 0:3) = reshape([1, 0, 0, 0, 1, 1, 0, 0, 1, 2, 1, 0, 1, 3, 3, 1], [4, 4])

contains

  !> n patches and n-1 transition lengths (>= 0). The logistic transitions
  !> default to the thesis's examples: midpoint in the middle of each
  !> transition, 0.99 point at its end; give both to override (blended u).
  function new_blended_surface(patches, transition, status, midpoint, u_99) result(b)
    type(blend_patch_t), intent(in) :: patches(:)
    real(wp), intent(in) :: transition(:)
    type(status_t), intent(out) :: status
    real(wp), intent(in), optional :: midpoint(:), u_99(:)
    type(blended_surface_t) :: b
    integer :: n, j
    real(wp), allocatable :: mid(:), u99(:)
    n = size(patches)
    if (n < 2 .or. n > max_patches .or. size(transition) /= n - 1) then
      call set_status(status, STATUS_INVALID_INPUT, 'blended surface: need 2..16 patches and ' // &
                      'one transition length between each pair')
      return
    end if
    if (any(transition < 0)) then
      call set_status(status, STATUS_INVALID_INPUT, 'blended surface: transition lengths must be >= 0')
      return
    end if
    do j = 1, n
      if (.not. allocated(patches(j)%surface)) then
        call set_status(status, STATUS_INVALID_INPUT, 'blended surface: a patch has no surface')
        return
      end if
      if (.not. patches(j)%u_max > patches(j)%u_min .or. patches(j)%v_max == patches(j)%v_min) then
        call set_status(status, STATUS_INVALID_INPUT, 'blended surface: each patch needs ' // &
                        'u_max > u_min and v_max /= v_min')
        return
      end if
    end do
    allocate (b%start(n))
    b%start(1) = 0
    do j = 2, n
      b%start(j) = b%start(j - 1) + patches(j - 1)%u_max - patches(j - 1)%u_min + transition(j - 1)
    end do
    b%u_end = b%start(n) + patches(n)%u_max - patches(n)%u_min
    allocate (mid(n - 1), u99(n - 1))
    do j = 1, n - 1
      mid(j) = b%start(j + 1) - transition(j)/2
      u99(j) = b%start(j + 1)
    end do
    if (present(midpoint) .neqv. present(u_99)) then
      call set_status(status, STATUS_INVALID_INPUT, 'blended surface: give both midpoint and u_99 or neither')
      return
    end if
    if (present(midpoint)) then
      if (size(midpoint) /= n - 1 .or. size(u_99) /= n - 1) then
        call set_status(status, STATUS_INVALID_INPUT, 'blended surface: one midpoint and one u_99 per transition')
        return
      end if
      mid = midpoint; u99 = u_99
    end if
    do j = 1, n - 1
      if (.not. u99(j) > mid(j)) then
        call set_status(status, STATUS_INVALID_INPUT, 'blended surface: each u_99 must lie after ' // &
                        'its midpoint (a zero-length transition needs an explicit midpoint and u_99)')
        return
      end if
    end do
    b%patches = patches
    b%midpoint = mid
    b%rate = [(logistic_rate(mid(j), u99(j)), j=1, n - 1)]
  end function new_blended_surface

  !> The weights w(0:3, j) of the patches at u (3.79 and derivatives).
  pure subroutine blended_weights(self, u, w)
    class(blended_surface_t), intent(in) :: self
    real(wp), intent(in) :: u
    real(wp), intent(out) :: w(0:, :)
    real(wp) :: lam(0:3, max_patches)
    integer :: j, n
    n = size(self%patches)
    do j = 1, n - 1
      call logistic(u, self%midpoint(j), self%rate(j), lam(:, j))
    end do
    call blend_weights(lam(:, 1:n - 1), w(:, 1:n))
  end subroutine blended_weights

  pure subroutine blended_evaluate(self, u, v, order, p, status)
    class(blended_surface_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    integer, intent(in) :: order
    type(surface_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    real(wp) :: w(0:3, max_patches), d(3, 0:3, 0:3), q(3, 0:3, 0:3), uj, vj, sv
    type(surface_point_t) :: pj
    integer :: n, j, i, k, m
    if (order < 0 .or. order > 3) then
      call set_status(status, STATUS_INVALID_INPUT, 'blended surface: order must be 0..3')
      return
    end if
    n = size(self%patches)
    call self%weights(u, w)
    d = 0
    do j = 1, n
      if (maxval(abs(w(0:order, j))) < skip_weight) cycle
      associate (pa => self%patches(j))
        uj = u - self%start(j) + pa%u_min                 ! (3.77)
        sv = pa%v_max - pa%v_min
        vj = sv*v + pa%v_min
        if (pa%swap_uv) then
          call pa%surface%evaluate(vj, uj, order, pj, status)
        else
          call pa%surface%evaluate(uj, vj, order, pj, status)
        end if
        if (.not. status%ok()) return
        q = 0
        q(:, 0, 0) = pj%r
        if (pa%swap_uv) then
          q(:, 1, 0) = pj%rv; q(:, 0, 1) = pj%ru
          q(:, 2, 0) = pj%rvv; q(:, 1, 1) = pj%ruv; q(:, 0, 2) = pj%ruu
          q(:, 3, 0) = pj%rvvv; q(:, 2, 1) = pj%ruvv; q(:, 1, 2) = pj%ruuv; q(:, 0, 3) = pj%ruuu
        else
          q(:, 1, 0) = pj%ru; q(:, 0, 1) = pj%rv
          q(:, 2, 0) = pj%ruu; q(:, 1, 1) = pj%ruv; q(:, 0, 2) = pj%rvv
          q(:, 3, 0) = pj%ruuu; q(:, 2, 1) = pj%ruuv; q(:, 1, 2) = pj%ruvv; q(:, 0, 3) = pj%rvvv
        end if
        do k = 1, 3                                        ! appendix D chain rule in v
          q(:, :, k) = q(:, :, k)*sv**k
        end do
      end associate
      do i = 0, order
        do k = 0, order - i
          do m = 0, i
            d(:, i, k) = d(:, i, k) + binom(m, i)*w(m, j)*q(:, i - m, k)
          end do
        end do
      end do
    end do
    p%order = order
    p%r = d(:, 0, 0)
    if (order >= 1) then
      p%ru = d(:, 1, 0); p%rv = d(:, 0, 1)
    end if
    if (order >= 2) then
      p%ruu = d(:, 2, 0); p%ruv = d(:, 1, 1); p%rvv = d(:, 0, 2)
    end if
    if (order >= 3) then
      p%ruuu = d(:, 3, 0); p%ruuv = d(:, 2, 1); p%ruvv = d(:, 1, 2); p%rvvv = d(:, 0, 3)
    end if
  end subroutine blended_evaluate

  pure subroutine blended_domain(self, u_min, u_max, v_min, v_max)
    class(blended_surface_t), intent(in) :: self
    real(wp), intent(out) :: u_min, u_max, v_min, v_max
    u_min = 0; u_max = self%u_end
    v_min = 0; v_max = 1
  end subroutine blended_domain

  pure function blended_describe(self) result(text)
    class(blended_surface_t), intent(in) :: self
    character(len=:), allocatable :: text
    character(len=12) :: buf
    write (buf, '(i0)') size(self%patches)
    text = 'blended surface of ' // trim(buf) // ' patches'
  end function blended_describe

  !> u is the patches' own u (shifted), in their unit when they agree; v is
  !> scaled to [0, 1].
  pure subroutine blended_parameter_units(self, u_units, v_units)
    class(blended_surface_t), intent(in) :: self
    character(len=:), allocatable, intent(out) :: u_units, v_units
    character(len=:), allocatable :: patch_u, patch_v, first
    integer :: j
    v_units = '1'
    do j = 1, size(self%patches)
      call self%patches(j)%surface%parameter_units(patch_u, patch_v)
      if (self%patches(j)%swap_uv) patch_u = patch_v
      if (j == 1) first = patch_u
      if (patch_u /= first) then
        u_units = '1'
        return
      end if
    end do
    u_units = first
    if (size(self%patches) == 0) u_units = '1'
  end subroutine blended_parameter_units
end module geometry_blended_surface
