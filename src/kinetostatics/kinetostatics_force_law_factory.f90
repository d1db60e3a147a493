!> The force laws inputs name, in one registry: a kind (force_law_kind_t: a
!> name, its parameters declared once, a builder) is registered once, and
!> `force_law_from_spec` builds a law of any registered kind from a spec
!> (base_spec: the kind's name and its parameters' values). Every model that
!> takes a friction law from its input (the contact scenario, the point
!> mass, the sled, the rider) builds it here; io reads a law's parameters by
!> the declarations `force_law_kinds` lists.
!>
!> Adding a kind: one module with the law (extend friction_law_t or
!> force_law_t) and a function returning its force_law_kind_t, and one line
!> in `register_builtin_laws` (or, from outside the library, one call of
!> `register_force_law` before the input is read). docs/DESIGN.md, "How to
!> add a force law".
!>
!> The registry is the one module variable of the layer: kinds, not
!> simulation state, kept by base_kind_registry (the surface kinds' registry
!> is the same), whose one OpenMP critical section covers every read and
!> change of it (the built-in kinds on first use, a registration, a
!> look-up), so that threads building models at once (a sweep's rides) find
!> it complete, and a kind registered meanwhile is seen whole or not at all;
!> a build copies its kind and runs outside it.
module kinetostatics_force_law_factory
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use base_spec, only: spec_t
  use base_kind_registry, only: kind_t, kind_box_t, kind_registry_t, box_kinds
  use kinetostatics_force_law, only: force_law_t, force_law_kind_t, law_place_t
  use kinetostatics_force_laws, only: coulomb_kind, viscous_kind, viscous_weight_kind, viscous_normal_kind
  implicit none (type, external)
  private
  public :: register_force_law, force_law_kinds, force_law_kind_index, force_law_from_spec, law_spec

  character(len=*), parameter :: WHAT = 'force law kind'
  type(kind_registry_t), save :: registry

contains

  !> The kinds every build knows, in the order inputs list them.
  subroutine builtins(kinds)
    type(kind_box_t), allocatable, intent(out) :: kinds(:)
    type(force_law_kind_t), allocatable :: known(:)
    known = [coulomb_kind(), viscous_kind(), viscous_weight_kind(), viscous_normal_kind()]
    ! (assigned first: gfortran 12 frees the components of function results in an
    ! array constructor passed as an argument twice: the run aborts in free)
    call box_kinds(known, kinds)
  end subroutine builtins

  !> Adds a kind; refused if its name is taken, empty or 'none' (no law), or it has no builder.
  subroutine register_force_law(kind, status)
    type(force_law_kind_t), intent(in) :: kind
    type(status_t), intent(inout) :: status
    if (.not. status%ok()) return
    if (.not. associated(kind%build) .or. len_trim(kind%name) == 0 .or. kind%name == 'none') then
      call set_status(status, STATUS_INVALID_INPUT, 'force law kind '''//kind%name//''': a kind needs a name '// &
                      'other than ''none'' and a builder')
      return
    end if
    call registry%register(builtins, WHAT, kind, status)
  end subroutine register_force_law

  !> Every registered kind (their names, parameters and meanings).
  function force_law_kinds() result(kinds)
    type(force_law_kind_t), allocatable :: kinds(:)
    type(kind_box_t), allocatable :: boxes(:)
    integer :: k
    call registry%copy_all(builtins, WHAT, boxes)
    allocate (kinds(size(boxes)))
    do k = 1, size(boxes)
      select type (kind => boxes(k)%kind)
      type is (force_law_kind_t)   ! (every kind registered here is one)
        kinds(k) = kind
      end select
    end do
  end function force_law_kinds

  !> The index of the kind `name` in force_law_kinds(), 0 if unknown.
  integer function force_law_kind_index(name) result(k)
    character(len=*), intent(in) :: name
    k = registry%find(builtins, WHAT, name)
  end function force_law_kind_index

  !> The spec of a law of kind `kind` with its parameter `name` = `value`
  !> (the others keep their defaults): a library caller's one-line law,
  !> law_spec('coulomb', 'mu', 0.2_wp).
  pure function law_spec(kind, name, value) result(spec)
    character(len=*), intent(in) :: kind, name
    real(wp), intent(in) :: value
    type(spec_t) :: spec
    spec%kind = kind
    call spec%set(name, [value])
  end function law_spec

  !> The law of `spec` acting at `place`; the spec is checked against its
  !> kind's declarations (defaults filled in) first.
  subroutine force_law_from_spec(spec, place, law, status)
    type(spec_t), intent(in) :: spec
    type(law_place_t), intent(in) :: place
    class(force_law_t), allocatable, intent(out) :: law
    type(status_t), intent(inout) :: status
    type(spec_t) :: completed
    class(kind_t), allocatable :: found
    call registry%copy_completed(builtins, WHAT, spec, 'force law '''//place%name//''': unknown kind', &
                                 'force law '''//place%name//''' ('//spec%kind//')', found, completed, status)
    if (.not. status%ok()) return
    select type (found)
    type is (force_law_kind_t)
      call found%build(completed, place, law, status)
    end select
  end subroutine force_law_from_spec
end module kinetostatics_force_law_factory
