from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_out import ErrorOut
from ...models.force_deflection_out import ForceDeflectionOut
from ...models.force_deflection_request import ForceDeflectionRequest
from ...types import Response


def _get_kwargs(
    *,
    body: ForceDeflectionRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/force-deflection",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> ErrorOut | ForceDeflectionOut | None:
    if response.status_code == 200:
        response_200 = ForceDeflectionOut.from_dict(response.json())

        return response_200

    if response.status_code == 401:
        response_401 = ErrorOut.from_dict(response.json())

        return response_401

    if response.status_code == 413:
        response_413 = ErrorOut.from_dict(response.json())

        return response_413

    if response.status_code == 422:
        response_422 = ErrorOut.from_dict(response.json())

        return response_422

    if response.status_code == 503:
        response_503 = ErrorOut.from_dict(response.json())

        return response_503

    if response.status_code == 504:
        response_504 = ErrorOut.from_dict(response.json())

        return response_504

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> Response[ErrorOut | ForceDeflectionOut]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: ForceDeflectionRequest,
) -> Response[ErrorOut | ForceDeflectionOut]:
    """Force-deflection curve along the least-energy stable branch

     Continuation over the deflections `dx` (a list, or `{start, stop, num}`; at most 501 points) at
    fixed `dy` (`tensegrity_opt.force_deflection`). `jumps` lists the force discontinuities (`kind`:
    `buckling` at dx -> 0+ from the stable straight chain, `leave_straight` from a straight chain that
    is not stable unloaded or at dy != 0, `snap` where the selected stable branch ends, `switch` where
    the least-energy stable branch changes while the old one stays stable; each with `delta` and a
    `label`); `branch = "all"` also returns every branch found at the first deflected point, with null
    where it no longer exists. Where a point has no stable equilibrium (a fold, the joint range) the
    curve stops: the answer is still 200, with the points before it, `success = false`, `ended_at` (that
    point and why) and a `message`. An answer over the server's `TENSEGRITY_MAX_RESPONSE_BYTES` (default
    8 MiB; n = 200 with 301 points and `branch = "all"` is ~40 MB) is refused with 422
    `response_too_large` on `dx`: ask for fewer points or `branch = "stable"`.

    Args:
        body (ForceDeflectionRequest): Force-deflection curve by continuation along the least-
            energy stable branch.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | ForceDeflectionOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    *,
    client: AuthenticatedClient | Client,
    body: ForceDeflectionRequest,
) -> ErrorOut | ForceDeflectionOut | None:
    """Force-deflection curve along the least-energy stable branch

     Continuation over the deflections `dx` (a list, or `{start, stop, num}`; at most 501 points) at
    fixed `dy` (`tensegrity_opt.force_deflection`). `jumps` lists the force discontinuities (`kind`:
    `buckling` at dx -> 0+ from the stable straight chain, `leave_straight` from a straight chain that
    is not stable unloaded or at dy != 0, `snap` where the selected stable branch ends, `switch` where
    the least-energy stable branch changes while the old one stays stable; each with `delta` and a
    `label`); `branch = "all"` also returns every branch found at the first deflected point, with null
    where it no longer exists. Where a point has no stable equilibrium (a fold, the joint range) the
    curve stops: the answer is still 200, with the points before it, `success = false`, `ended_at` (that
    point and why) and a `message`. An answer over the server's `TENSEGRITY_MAX_RESPONSE_BYTES` (default
    8 MiB; n = 200 with 301 points and `branch = "all"` is ~40 MB) is refused with 422
    `response_too_large` on `dx`: ask for fewer points or `branch = "stable"`.

    Args:
        body (ForceDeflectionRequest): Force-deflection curve by continuation along the least-
            energy stable branch.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | ForceDeflectionOut
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: ForceDeflectionRequest,
) -> Response[ErrorOut | ForceDeflectionOut]:
    """Force-deflection curve along the least-energy stable branch

     Continuation over the deflections `dx` (a list, or `{start, stop, num}`; at most 501 points) at
    fixed `dy` (`tensegrity_opt.force_deflection`). `jumps` lists the force discontinuities (`kind`:
    `buckling` at dx -> 0+ from the stable straight chain, `leave_straight` from a straight chain that
    is not stable unloaded or at dy != 0, `snap` where the selected stable branch ends, `switch` where
    the least-energy stable branch changes while the old one stays stable; each with `delta` and a
    `label`); `branch = "all"` also returns every branch found at the first deflected point, with null
    where it no longer exists. Where a point has no stable equilibrium (a fold, the joint range) the
    curve stops: the answer is still 200, with the points before it, `success = false`, `ended_at` (that
    point and why) and a `message`. An answer over the server's `TENSEGRITY_MAX_RESPONSE_BYTES` (default
    8 MiB; n = 200 with 301 points and `branch = "all"` is ~40 MB) is refused with 422
    `response_too_large` on `dx`: ask for fewer points or `branch = "stable"`.

    Args:
        body (ForceDeflectionRequest): Force-deflection curve by continuation along the least-
            energy stable branch.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | ForceDeflectionOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: ForceDeflectionRequest,
) -> ErrorOut | ForceDeflectionOut | None:
    """Force-deflection curve along the least-energy stable branch

     Continuation over the deflections `dx` (a list, or `{start, stop, num}`; at most 501 points) at
    fixed `dy` (`tensegrity_opt.force_deflection`). `jumps` lists the force discontinuities (`kind`:
    `buckling` at dx -> 0+ from the stable straight chain, `leave_straight` from a straight chain that
    is not stable unloaded or at dy != 0, `snap` where the selected stable branch ends, `switch` where
    the least-energy stable branch changes while the old one stays stable; each with `delta` and a
    `label`); `branch = "all"` also returns every branch found at the first deflected point, with null
    where it no longer exists. Where a point has no stable equilibrium (a fold, the joint range) the
    curve stops: the answer is still 200, with the points before it, `success = false`, `ended_at` (that
    point and why) and a `message`. An answer over the server's `TENSEGRITY_MAX_RESPONSE_BYTES` (default
    8 MiB; n = 200 with 301 points and `branch = "all"` is ~40 MB) is refused with 422
    `response_too_large` on `dx`: ask for fewer points or `branch = "stable"`.

    Args:
        body (ForceDeflectionRequest): Force-deflection curve by continuation along the least-
            energy stable branch.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | ForceDeflectionOut
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
