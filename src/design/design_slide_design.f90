!> The design space of the geometry optimisation (design_geometry_optimization):
!> a circular tube slide around a spline through points, some coordinates of
!> which are the design variables with their bounds (table 4.12's design), or
!> around a chain of standard elements (geometry_slide_elements), some
!> parameters of which are the design variables (a curve's radius, turning
!> angle, an element's slope or length; a bowl's entry radius, wall slope
!> and drop; a funnel's length, slope and widest radius; a drop's slope and
!> curve-out radius: the parts a slide is built from); the slide of a
!> design; the starts of a multi-start.
module design_slide_design
  use base_kinds, only: wp
  use base_status, only: status_t, prefix_status, STATUS_INVALID_INPUT, STATUS_DOMAIN
  use geometry_tube, only: tube_surface_t
  use geometry_slide_builder, only: slide_description_t, section_part_description_t, build_slide, &
    slide_elements_description_t
  use geometry_slide_elements, only: slide_element_t
  use numerics_random, only: random_stream_t, new_random_stream, next_uniform
  implicit none (type, external)
  private
  public :: slide_design_t, table_4_12_design, design_points, start_x, build_design_slide, start_points
  public :: design_elements, parameter_value, set_parameter, PARAMETER_LENGTH, PARAMETER_SLOPE, PARAMETER_RADIUS, &
    PARAMETER_ANGLE, PARAMETER_DROP, parameter_names, parameter_units

  !> The element parameters a design variable can be (slide_element_t's
  !> length, slope_deg, radius, angle_deg, drop), their names (those of
  !> &slide_elements, docs/geometry.md) and units. Which element kinds have
  !> which as a design variable: io_element_design_config.
  integer, parameter :: PARAMETER_LENGTH = 1, PARAMETER_SLOPE = 2, PARAMETER_RADIUS = 3, PARAMETER_ANGLE = 4, &
                        PARAMETER_DROP = 5
  character(len=*), parameter :: parameter_names(5) = [character(len=6) :: 'length', 'slope', 'radius', 'angle', &
                                                       'drop']
  character(len=*), parameter :: parameter_units(5) = [character(len=3) :: 'm', 'deg', 'm', 'deg', 'm']

  !> A tube slide around a spline through points, and which coordinates
  !> move; or around a chain of elements, and which parameters move.
  type :: slide_design_t
    real(wp), allocatable :: points(:, :)     !< m, 3 x n: the start design
    integer, allocatable :: point(:)          !< the point of each design variable (1-based)
    integer, allocatable :: coordinate(:)     !< its coordinate (1 x, 2 y, 3 z)
    logical :: from_elements = .false.        !< the design is `chain`, not `points`
    type(slide_elements_description_t) :: chain   !< the start design (from_elements)
    integer, allocatable :: element(:)        !< the element of each design variable (1-based; from_elements)
    integer, allocatable :: parameter(:)      !< its parameter (PARAMETER_*)
    real(wp), allocatable :: lower(:), upper(:)   !< bounds of the design variables (m; from_elements: m or deg)
    real(wp) :: radius = 0.7_wp               !< m, tube radius
    real(wp) :: horizon(3) = [0.0_wp, 0.0_wp, 1.0_wp]
    integer :: degree = 5                     !< of the interpolating spline (see docs/design.md)
    real(wp) :: smoothing = 0                 !< FITPACK smoothing (m^2); 0 interpolates
    integer :: check_samples = 400            !< folding check along the centerline
  end type slide_design_t

contains

  !> Table 4.12's slide before optimisation: P0..P8, the five moving
  !> coordinates P2.y, P3.y, P4.x, P5.y, P6.y and their bounds (4.49; the
  !> lower bound printed as "u" is l).
  function table_4_12_design() result(d)
    type(slide_design_t) :: d
    d%points = reshape([0.0_wp, 5.0_wp, 3.0_wp, 0.2_wp, 5.0_wp, 2.9_wp, 3.0_wp, 5.0_wp, 2.3_wp, &
                        5.0_wp, 5.0_wp, 1.7_wp, 6.0_wp, 7.0_wp, 1.1_wp, 5.0_wp, 9.0_wp, 0.5_wp, &
                        3.0_wp, 9.0_wp, 0.3_wp, 0.2_wp, 9.0_wp, 0.03_wp, 0.0_wp, 9.0_wp, 0.0_wp], [3, 9])
    d%point = [3, 4, 5, 6, 7]
    d%coordinate = [2, 2, 1, 2, 2]
    d%lower = [4.0_wp, 4.0_wp, 5.0_wp, 8.0_wp, 8.0_wp]
    d%upper = [6.0_wp, 6.0_wp, 7.0_wp, 10.0_wp, 10.0_wp]
  end function table_4_12_design

  !> The points with the design variables set to x (none for an element design).
  pure function design_points(design, x) result(points)
    type(slide_design_t), intent(in) :: design
    real(wp), intent(in) :: x(:)
    real(wp), allocatable :: points(:, :)
    integer :: k
    if (design%from_elements) then
      allocate (points(3, 0))
      return
    end if
    points = design%points
    do k = 1, size(x)
      points(design%coordinate(k), design%point(k)) = x(k)
    end do
  end function design_points

  !> The elements of an element design with the design variables set to x.
  pure function design_elements(design, x) result(elements)
    type(slide_design_t), intent(in) :: design
    real(wp), intent(in) :: x(:)
    type(slide_element_t), allocatable :: elements(:)
    integer :: k
    elements = design%chain%elements
    do k = 1, size(x)
      call set_parameter(elements(design%element(k)), design%parameter(k), x(k))
    end do
  end function design_elements

  !> Sets parameter `kind` (PARAMETER_*) of element e to `value`.
  elemental subroutine set_parameter(e, kind, value)
    type(slide_element_t), intent(inout) :: e
    integer, intent(in) :: kind
    real(wp), intent(in) :: value
    select case (kind)
    case (PARAMETER_LENGTH); e%length = value
    case (PARAMETER_SLOPE); e%slope_deg = value
    case (PARAMETER_RADIUS); e%radius = value
    case (PARAMETER_ANGLE); e%angle_deg = value
    case (PARAMETER_DROP); e%drop = value
    end select
  end subroutine set_parameter

  !> The value of parameter `kind` (PARAMETER_*) of element e.
  elemental real(wp) function parameter_value(e, kind) result(value)
    type(slide_element_t), intent(in) :: e
    integer, intent(in) :: kind
    select case (kind)
    case (PARAMETER_LENGTH); value = e%length
    case (PARAMETER_SLOPE); value = e%slope_deg
    case (PARAMETER_RADIUS); value = e%radius
    case (PARAMETER_ANGLE); value = e%angle_deg
    case default; value = e%drop
    end select
  end function parameter_value

  !> The x of the start design.
  pure function start_x(design) result(x)
    type(slide_design_t), intent(in) :: design
    real(wp) :: x(size(design%lower))
    integer :: k
    do k = 1, size(x)
      if (design%from_elements) then
        x(k) = parameter_value(design%chain%elements(design%element(k)), design%parameter(k))
      else
        x(k) = design%points(design%coordinate(k), design%point(k))
      end if
    end do
  end function start_x

  !> The tube slide of design x.
  subroutine build_design_slide(design, x, slide, status)
    type(slide_design_t), intent(in) :: design
    real(wp), intent(in) :: x(:)
    type(tube_surface_t), intent(out) :: slide
    type(status_t), intent(out) :: status
    type(slide_description_t) :: d
    if (design%from_elements) then
      d%kind = 'slide'
      d%elements = design%chain
      d%elements%elements = design_elements(design, x)
    else
      d%kind = 'tube'
      d%centerline%kind = 'points'
      d%centerline%points = design_points(design, x)
      d%centerline%degree = design%degree
      d%centerline%smoothing = design%smoothing
      d%centerline%horizon = design%horizon
    end if
    d%section%parts = [section_part_description_t(kind='circle', radius=design%radius)]
    d%check_samples = design%check_samples
    status = status_t()
    call build_slide(d, slide, status)
    if (.not. status%ok()) then
      call prefix_status(status, 'slide design')
      if (status%code == STATUS_INVALID_INPUT) status%code = STATUS_DOMAIN
    end if
  end subroutine build_design_slide

  !> The start points, one per column: the given design, then n - 1 drawn
  !> uniformly in the bounds' box from the stream of `seed`, each drawn
  !> again (up to max_draws times) while its slide cannot be built (folds):
  !> such a start would be lost, and building costs no ride.
  function start_points(design, n, seed) result(points)
    type(slide_design_t), intent(in) :: design
    integer, intent(in) :: n, seed
    real(wp), allocatable :: points(:, :)
    integer, parameter :: max_draws = 100
    type(random_stream_t) :: stream
    type(tube_surface_t) :: slide
    type(status_t) :: built
    real(wp) :: u
    integer :: k, j, draw
    allocate (points(size(design%lower), n))
    points(:, 1) = start_x(design)
    stream = new_random_stream(seed)
    do k = 2, n
      do draw = 1, max_draws
        do j = 1, size(points, 1)
          call next_uniform(stream, u)
          points(j, k) = design%lower(j) + u*(design%upper(j) - design%lower(j))
        end do
        call build_design_slide(design, points(:, k), slide, built)
        if (built%ok()) exit
      end do
    end do
  end function start_points
end module design_slide_design
