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
!> simulation state, with their index by name (base_kind_index). Every read
!> and change of it (the built-in kinds on first use, a registration, a
!> look-up) runs inside one OpenMP critical section, so that threads
!> building models at once (a sweep's rides) find it complete, and a kind
!> registered meanwhile is seen whole or not at all; a build copies its kind
!> and runs outside it.
module kinetostatics_force_law_factory
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use base_spec, only: spec_t, complete_spec
  use base_kind_index, only: kind_index_t
  use kinetostatics_force_law, only: force_law_t, force_law_kind_t, law_place_t
  use kinetostatics_force_laws, only: coulomb_kind, viscous_kind, viscous_weight_kind, viscous_normal_kind
  implicit none (type, external)
  private
  public :: register_force_law, force_law_kinds, force_law_kind_index, force_law_from_spec, law_spec

  type(force_law_kind_t), allocatable, save :: registry(:)
  type(kind_index_t), save :: names   !< registry(k)%name is names' k-th

contains

  !> The kinds every build knows, in the order inputs list them (inside the
  !> critical section, on first use).
  subroutine ensure_builtins()
    type(status_t) :: status
    integer :: k
    if (allocated(registry)) return
    registry = [coulomb_kind(), viscous_kind(), viscous_weight_kind(), viscous_normal_kind()]
    do k = 1, size(registry)
      call names%add(registry(k)%name, 'force law kind', status)
    end do
  end subroutine ensure_builtins

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
    !$omp critical (force_law_registry)
    call ensure_builtins()
    call names%add(kind%name, 'force law kind', status)
    if (status%ok()) registry = [registry, kind]
    !$omp end critical (force_law_registry)
  end subroutine register_force_law

  !> Every registered kind (their names, parameters and meanings).
  function force_law_kinds() result(kinds)
    type(force_law_kind_t), allocatable :: kinds(:)
    !$omp critical (force_law_registry)
    call ensure_builtins()
    kinds = registry
    !$omp end critical (force_law_registry)
  end function force_law_kinds

  !> The index of the kind `name` in force_law_kinds(), 0 if unknown.
  integer function force_law_kind_index(name) result(k)
    character(len=*), intent(in) :: name
    !$omp critical (force_law_registry)
    call ensure_builtins()
    k = names%find(name)
    !$omp end critical (force_law_registry)
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
    type(force_law_kind_t) :: kind
    character(len=:), allocatable :: known
    integer :: k
    if (.not. status%ok()) return
    !$omp critical (force_law_registry)
    call ensure_builtins()
    k = names%find(spec%kind)
    if (k > 0) then
      kind = registry(k)
    else
      known = names%listing()
    end if
    !$omp end critical (force_law_registry)
    if (k == 0) then
      call set_status(status, STATUS_INVALID_INPUT, 'force law '''//place%name//''': unknown kind '''// &
                      spec%kind//'''; the kinds are'//known)
      return
    end if
    completed = spec
    call complete_spec(completed, kind%parameters, 'force law '''//place%name//''' ('//spec%kind//')', status)
    if (status%ok()) call kind%build(completed, place, law, status)
  end subroutine force_law_from_spec
end module kinetostatics_force_law_factory
