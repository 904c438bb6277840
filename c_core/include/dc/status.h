/* Status codes shared by every c_core law (GSL style: a value plus a status).
   Every public function keeps these promises (tests/unit/test_fuzz.c): an
   error leaves every output untouched (exception: the parameter checks of
   dc/contract.h fill their dc_param_error, which is the report), DC_OK never
   comes with a NaN or Inf output, non-finite inputs are DC_EDOM. */
#ifndef DC_STATUS_H
#define DC_STATUS_H

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
  DC_OK = 0,        /* result valid to the stated accuracy */
  DC_EDOM = 1,      /* an input lies outside the documented domain; outputs untouched */
  DC_ENOCONV = 2,   /* an iteration did not converge; outputs hold the last iterate */
  DC_ERANGE = 3     /* result would overflow or underflow */
} dc_status;

/* Short English name of a status code, for error messages. */
const char *dc_status_str(int status);

#ifdef __cplusplus
}
#endif
#endif
