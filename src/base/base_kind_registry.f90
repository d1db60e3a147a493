!> The one registry of kinds that inputs name (the surface kinds of
!> geometry_surface_factory, the force laws of kinetostatics_force_law_factory):
!> a kind (kind_t: a name, a meaning, its parameters declared once; each
!> factory's kind extends it with its builder) is registered once, found by
!> name, listed in the order registered, and copied out whole for a build.
!> The kinds every build knows come from the factory's `builtins` on first
!> use.
!>
!> Threads: a factory keeps its registry in a module variable (kinds, not
!> simulation state). Every access here, the built-in kinds on first use
!> included, runs inside ONE OpenMP critical section (base_kind_registry)
!> that covers the kinds and their index alike, so that a registration in
!> one thread and a look-up or a build in another see all of a kind or none
!> of it (an index read while another thread reallocates it is a data race).
!> A build copies its kind out and runs outside the section. The base layer
!> is compiled with OpenMP for it (src/CMakeLists.txt; without -fopenmp the
!> directive is a comment and there is no lock: `registry_locks` says which,
!> and test_kind_registration checks it). Copies go out
!> through intent(out) arguments, not function results (gfortran 12 frees a
!> polymorphic function result twice).
module base_kind_registry
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use base_spec, only: parameter_t, spec_t, complete_spec
  use base_kind_index, only: kind_index_t
  implicit none (type, external)
  private
  public :: kind_t, kind_box_t, kind_registry_t, builtins_i, registry_locks, box_kinds

  !> What every kind has; a factory's kind extends it with its builder.
  type :: kind_t
    character(len=:), allocatable :: name, meaning
    type(parameter_t), allocatable :: parameters(:)
  end type kind_t

  type :: kind_box_t
    class(kind_t), allocatable :: kind
  end type kind_box_t

  type :: kind_registry_t
    private
    type(kind_box_t), allocatable :: kinds(:)
    type(kind_index_t) :: names   !< kinds(k)%kind%name is names' k-th
  contains
    procedure :: register, copy_all, find, copy_kind, copy_completed
  end type kind_registry_t

  abstract interface
    !> The kinds every build knows, in the order inputs list them.
    subroutine builtins_i(kinds)
      import :: kind_box_t
      type(kind_box_t), allocatable, intent(out) :: kinds(:)
    end subroutine builtins_i
  end interface

contains

  !> Whether the registry's critical section is compiled in (OpenMP on).
  pure logical function registry_locks() result(locks)
    locks = .false.
    !$ locks = .true.
  end function registry_locks

  !> The kinds `known` boxed (copies), as a factory's `builtins` gives them.
  subroutine box_kinds(known, kinds)
    class(kind_t), intent(in) :: known(:)
    type(kind_box_t), allocatable, intent(out) :: kinds(:)
    integer :: k
    allocate (kinds(size(known)))
    do k = 1, size(known)
      allocate (kinds(k)%kind, source=known(k))
    end do
  end subroutine box_kinds

  !> The built-in kinds on first use (inside the critical section).
  subroutine ensure_builtins(self, builtins, what)
    type(kind_registry_t), intent(inout) :: self
    procedure(builtins_i) :: builtins
    character(len=*), intent(in) :: what
    type(status_t) :: status
    integer :: k
    if (allocated(self%kinds)) return
    call builtins(self%kinds)
    do k = 1, size(self%kinds)
      call self%names%add(self%kinds(k)%kind%name, what, status)
    end do
  end subroutine ensure_builtins

  !> Adds `kind`; refused if its name is empty or taken (`what` names the
  !> registry in the message: 'surface kind', 'force law kind').
  subroutine register(self, builtins, what, kind, status)
    class(kind_registry_t), intent(inout) :: self
    procedure(builtins_i) :: builtins
    character(len=*), intent(in) :: what
    class(kind_t), intent(in) :: kind
    type(status_t), intent(inout) :: status
    type(kind_box_t), allocatable :: grown(:)
    integer :: k, n
    if (.not. status%ok()) return
    !$omp critical (base_kind_registry)
    call ensure_builtins(self, builtins, what)
    call self%names%add(kind%name, what, status)
    if (status%ok()) then
      n = size(self%kinds)
      allocate (grown(n + 1))
      do k = 1, n
        call move_alloc(self%kinds(k)%kind, grown(k)%kind)
      end do
      allocate (grown(n + 1)%kind, source=kind)
      call move_alloc(grown, self%kinds)
    end if
    !$omp end critical (base_kind_registry)
  end subroutine register

  !> Every registered kind, in the order registered.
  subroutine copy_all(self, builtins, what, kinds)
    class(kind_registry_t), intent(inout) :: self
    procedure(builtins_i) :: builtins
    character(len=*), intent(in) :: what
    type(kind_box_t), allocatable, intent(out) :: kinds(:)
    integer :: k
    !$omp critical (base_kind_registry)
    call ensure_builtins(self, builtins, what)
    allocate (kinds(size(self%kinds)))
    do k = 1, size(kinds)
      allocate (kinds(k)%kind, source=self%kinds(k)%kind)
    end do
    !$omp end critical (base_kind_registry)
  end subroutine copy_all

  !> The index of the kind `name` in the order registered, 0 if unknown.
  integer function find(self, builtins, what, name) result(k)
    class(kind_registry_t), intent(inout) :: self
    procedure(builtins_i) :: builtins
    character(len=*), intent(in) :: what, name
    !$omp critical (base_kind_registry)
    call ensure_builtins(self, builtins, what)
    k = self%names%find(name)
    !$omp end critical (base_kind_registry)
  end function find

  !> A copy of the kind `name` (not allocated if unknown; `known` then lists
  !> the names, each quoted after a blank, for the caller's message).
  subroutine copy_kind(self, builtins, what, name, kind, known)
    class(kind_registry_t), intent(inout) :: self
    procedure(builtins_i) :: builtins
    character(len=*), intent(in) :: what, name
    class(kind_t), allocatable, intent(out) :: kind
    character(len=:), allocatable, intent(out) :: known
    integer :: k
    !$omp critical (base_kind_registry)
    call ensure_builtins(self, builtins, what)
    k = self%names%find(name)
    if (k > 0) then
      allocate (kind, source=self%kinds(k)%kind)
    else
      known = self%names%listing()
    end if
    !$omp end critical (base_kind_registry)
  end subroutine copy_kind

  !> A copy of the kind of `spec` and the spec checked against its
  !> declarations, defaults filled in (complete_spec; `context` names it in
  !> a message). An unknown kind: STATUS_INVALID_INPUT with `unknown` (e.g.
  !> 'unknown surface kind'), the kind's name and the known names, and
  !> `kind` not allocated. The factory then builds with its own kind's builder.
  subroutine copy_completed(self, builtins, what, spec, unknown, context, kind, completed, status)
    class(kind_registry_t), intent(inout) :: self
    procedure(builtins_i) :: builtins
    character(len=*), intent(in) :: what, unknown, context
    type(spec_t), intent(in) :: spec
    class(kind_t), allocatable, intent(out) :: kind
    type(spec_t), intent(out) :: completed
    type(status_t), intent(inout) :: status
    character(len=:), allocatable :: known
    if (.not. status%ok()) return
    call self%copy_kind(builtins, what, spec%kind, kind, known)
    if (.not. allocated(kind)) then
      call set_status(status, STATUS_INVALID_INPUT, unknown//' '''//spec%kind//'''; the kinds are'//known)
      return
    end if
    completed = spec
    call complete_spec(completed, kind%parameters, context, status)
  end subroutine copy_completed
end module base_kind_registry
