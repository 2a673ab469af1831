// Reset for the emulated Cortex-M4 (qemu mps2-an386) and the M0 build (run on mps2-an385): a vector table at
// address 0, and a reset handler that turns on the FPU before newlib's
// _start runs (hard-float code would fault on its first FPU instruction).
#include <stdint.h>

extern void _start(void);
extern uint32_t __stack_top;

static void reset(void) {
#if defined(__ARM_FP)  // hard float (M4); the M0 build has no FPU to turn on
  volatile uint32_t* cpacr = (volatile uint32_t*)0xE000ED88u;
  *cpacr |= 0xFu << 20;  // CP10 and CP11: full access
#endif
  __asm volatile("dsb\n\tisb");
  _start();
  for (;;) {
  }
}

static void halt(void) {
  for (;;) {
  }
}

__attribute__((section(".vectors"), used)) static const void* const vectors[16] = {
    &__stack_top, (const void*)reset, (const void*)halt, (const void*)halt,
    (const void*)halt, (const void*)halt, (const void*)halt, 0, 0, 0, 0,
    (const void*)halt, (const void*)halt, 0, (const void*)halt, (const void*)halt};
