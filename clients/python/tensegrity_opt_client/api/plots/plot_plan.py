from http import HTTPStatus
from io import BytesIO
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_out import ErrorOut
from ...models.plot_plan_request import PlotPlanRequest
from ...types import File, Response


def _get_kwargs(
    *,
    body: PlotPlanRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/plots/plan",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> ErrorOut | File | None:
    if response.status_code == 200:
        response_200 = File(payload=BytesIO(response.content))

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


def _build_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Response[ErrorOut | File]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: PlotPlanRequest,
) -> Response[ErrorOut | File]:
    """Figure: a rest-length plan, per step the rest lengths, the margin and the tip path with the targets

     The plan of `/v1/control/plan` (the same body, computed for the figure): the rest lengths of every
    spring per step (spring 1 solid, spring 2 dashed, one colour per segment), the stability margin per
    step with the required one dotted, and the tip path with the targets; infeasible steps are shaded
    and their best reachable tips marked, the legend below the panels. At most the server's
    `TENSEGRITY_MAX_TRAJECTORY_STEPS` targets (default 2000; above: 422 `too_many_steps` naming
    `targets`), chains of 2 to 60 segments (as `/v1/design/*`: the IPOPT fallback is the same problem).
    The plan runs in a solver process and stops shortly before the server's time limit, answering the
    steps done (200, `status: "time_limit"`, `success: false`) instead of a 504. A step costs ~4 ms by
    Newton with its verification (n = 4), tens of milliseconds by IPOPT; the first plan for a chain
    length builds its IPOPT problem in one call nothing interrupts (n = 40: ~1.5 s; n = 60: ~40 s, a
    504, and the process is replaced). Answers `image/png`, or `image/svg+xml` with `"format": "svg"`
    (or, without `format`, an `Accept` header preferring `image/svg+xml`); `dpi` sets the PNG
    resolution.

    Args:
        body (PlotPlanRequest): The plan of `/v1/control/plan` computed for the figure (the same
            body): rest lengths, tip path, margin.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | File]
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
    body: PlotPlanRequest,
) -> ErrorOut | File | None:
    """Figure: a rest-length plan, per step the rest lengths, the margin and the tip path with the targets

     The plan of `/v1/control/plan` (the same body, computed for the figure): the rest lengths of every
    spring per step (spring 1 solid, spring 2 dashed, one colour per segment), the stability margin per
    step with the required one dotted, and the tip path with the targets; infeasible steps are shaded
    and their best reachable tips marked, the legend below the panels. At most the server's
    `TENSEGRITY_MAX_TRAJECTORY_STEPS` targets (default 2000; above: 422 `too_many_steps` naming
    `targets`), chains of 2 to 60 segments (as `/v1/design/*`: the IPOPT fallback is the same problem).
    The plan runs in a solver process and stops shortly before the server's time limit, answering the
    steps done (200, `status: "time_limit"`, `success: false`) instead of a 504. A step costs ~4 ms by
    Newton with its verification (n = 4), tens of milliseconds by IPOPT; the first plan for a chain
    length builds its IPOPT problem in one call nothing interrupts (n = 40: ~1.5 s; n = 60: ~40 s, a
    504, and the process is replaced). Answers `image/png`, or `image/svg+xml` with `"format": "svg"`
    (or, without `format`, an `Accept` header preferring `image/svg+xml`); `dpi` sets the PNG
    resolution.

    Args:
        body (PlotPlanRequest): The plan of `/v1/control/plan` computed for the figure (the same
            body): rest lengths, tip path, margin.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | File
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: PlotPlanRequest,
) -> Response[ErrorOut | File]:
    """Figure: a rest-length plan, per step the rest lengths, the margin and the tip path with the targets

     The plan of `/v1/control/plan` (the same body, computed for the figure): the rest lengths of every
    spring per step (spring 1 solid, spring 2 dashed, one colour per segment), the stability margin per
    step with the required one dotted, and the tip path with the targets; infeasible steps are shaded
    and their best reachable tips marked, the legend below the panels. At most the server's
    `TENSEGRITY_MAX_TRAJECTORY_STEPS` targets (default 2000; above: 422 `too_many_steps` naming
    `targets`), chains of 2 to 60 segments (as `/v1/design/*`: the IPOPT fallback is the same problem).
    The plan runs in a solver process and stops shortly before the server's time limit, answering the
    steps done (200, `status: "time_limit"`, `success: false`) instead of a 504. A step costs ~4 ms by
    Newton with its verification (n = 4), tens of milliseconds by IPOPT; the first plan for a chain
    length builds its IPOPT problem in one call nothing interrupts (n = 40: ~1.5 s; n = 60: ~40 s, a
    504, and the process is replaced). Answers `image/png`, or `image/svg+xml` with `"format": "svg"`
    (or, without `format`, an `Accept` header preferring `image/svg+xml`); `dpi` sets the PNG
    resolution.

    Args:
        body (PlotPlanRequest): The plan of `/v1/control/plan` computed for the figure (the same
            body): rest lengths, tip path, margin.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | File]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: PlotPlanRequest,
) -> ErrorOut | File | None:
    """Figure: a rest-length plan, per step the rest lengths, the margin and the tip path with the targets

     The plan of `/v1/control/plan` (the same body, computed for the figure): the rest lengths of every
    spring per step (spring 1 solid, spring 2 dashed, one colour per segment), the stability margin per
    step with the required one dotted, and the tip path with the targets; infeasible steps are shaded
    and their best reachable tips marked, the legend below the panels. At most the server's
    `TENSEGRITY_MAX_TRAJECTORY_STEPS` targets (default 2000; above: 422 `too_many_steps` naming
    `targets`), chains of 2 to 60 segments (as `/v1/design/*`: the IPOPT fallback is the same problem).
    The plan runs in a solver process and stops shortly before the server's time limit, answering the
    steps done (200, `status: "time_limit"`, `success: false`) instead of a 504. A step costs ~4 ms by
    Newton with its verification (n = 4), tens of milliseconds by IPOPT; the first plan for a chain
    length builds its IPOPT problem in one call nothing interrupts (n = 40: ~1.5 s; n = 60: ~40 s, a
    504, and the process is replaced). Answers `image/png`, or `image/svg+xml` with `"format": "svg"`
    (or, without `format`, an `Accept` header preferring `image/svg+xml`); `dpi` sets the PNG
    resolution.

    Args:
        body (PlotPlanRequest): The plan of `/v1/control/plan` computed for the figure (the same
            body): rest lengths, tip path, margin.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | File
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
