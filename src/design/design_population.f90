!> The population of a robust geometry optimisation (docs/design.md, "Robust
!> design over a population"), built from its description: the rows of a
!> sweep (design_sweep's sweep_rows: one value of every swept variable per
!> row, crossed and paired as a sweep's) over the optimiser's body and start.
!> A member is one ride of the optimiser's cuboid:
!>   mass          the body's mass (kg);
!>   height        the body's length along the slide (m, a person's height),
!>                 its width, thickness (body height) and com_height scaled
!>                 with it from setup%body;
!>   v0            where on the first section it starts (rad, pi/2 the bottom);
!>   speed0        its start speed (m/s);
!>   heading0_deg  its start direction to the centerline (deg): swept, each
!>                 row rides from its own; else every row rides from each of
!>                 setup%start_angles (the angles fastest).
!> The other swept variables of a sweep (sex, mu, u0, the water's) are no
!> variables of the cuboid: a reader refuses them (io_optimization_population).
module design_population
  use base_kinds, only: wp
  use base_constants, only: pi
  use design_sweep, only: N_SWEPT, V_SEX, V_MASS, V_HEIGHT, V_V0, V_HEADING, V_SPEED
  use design_robust_cost, only: ride_member_t
  use design_geometry_optimization, only: optimization_setup_t
  implicit none (type, external)
  private
  public :: population_base, set_population

contains

  !> The value of each swept variable that the population does not sweep:
  !> the optimiser's body and start (sex 1, the others 0; heading in degrees
  !> is not used: without it swept the rides take setup%start_angles).
  pure function population_base(setup) result(base)
    type(optimization_setup_t), intent(in) :: setup
    real(wp) :: base(N_SWEPT)
    base = 0
    base(V_SEX) = 1
    base(V_MASS) = setup%body%mass
    base(V_HEIGHT) = setup%body%length
    base(V_V0) = setup%start_v
    base(V_SPEED) = setup%start_speed
  end function population_base

  !> setup%members and setup%start_angles (one per member) from the rows
  !> (N_SWEPT x rows, heading0_deg in degrees): with heading_swept one member
  !> per row from its heading, else one per row and start angle, row i's
  !> members (i - 1) n_angles + 1 .. i n_angles.
  pure subroutine set_population(setup, rows, heading_swept)
    type(optimization_setup_t), intent(inout) :: setup
    real(wp), intent(in) :: rows(:, :)
    logical, intent(in) :: heading_swept
    real(wp), allocatable :: angles(:)
    integer :: i, j, n_rows, n_angles

    n_rows = size(rows, 2)
    if (heading_swept) then
      angles = rows(V_HEADING, :)*pi/180
      n_angles = 1
    else
      angles = setup%start_angles
      n_angles = size(angles)
    end if
    if (allocated(setup%members)) deallocate (setup%members)
    allocate (setup%members(n_rows*n_angles))
    deallocate (setup%start_angles)
    allocate (setup%start_angles(n_rows*n_angles))
    do i = 1, n_rows
      do j = 1, n_angles
        setup%members((i - 1)*n_angles + j) = member(rows(:, i))
        setup%start_angles((i - 1)*n_angles + j) = angles(merge(i, j, heading_swept))
      end do
    end do

  contains

    !> The member of one row: setup%body scaled to its height.
    pure function member(v) result(m)
      real(wp), intent(in) :: v(N_SWEPT)
      type(ride_member_t) :: m
      real(wp) :: scale
      scale = v(V_HEIGHT)/setup%body%length
      m%body = setup%body
      m%body%mass = v(V_MASS)
      m%body%length = v(V_HEIGHT)
      m%body%width = setup%body%width*scale
      m%body%height = setup%body%height*scale
      m%body%com_height = setup%body%com_height*scale
      m%height = v(V_HEIGHT)
      m%speed = v(V_SPEED)
      m%v = v(V_V0)
    end function member
  end subroutine set_population
end module design_population
