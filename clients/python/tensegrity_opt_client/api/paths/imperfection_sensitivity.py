from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_out import ErrorOut
from ...models.imperfection_sensitivity_out import ImperfectionSensitivityOut
from ...models.imperfection_sensitivity_request import ImperfectionSensitivityRequest
from ...types import Response


def _get_kwargs(
    *,
    body: ImperfectionSensitivityRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/imperfection-sensitivity",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> ErrorOut | ImperfectionSensitivityOut | None:
    if response.status_code == 200:
        response_200 = ImperfectionSensitivityOut.from_dict(response.json())

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
) -> Response[ErrorOut | ImperfectionSensitivityOut]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: ImperfectionSensitivityRequest,
) -> Response[ErrorOut | ImperfectionSensitivityOut]:
    """The limit load an imperfect arm reaches, against the imperfection's amplitude

     Koiter's imperfection-sensitivity curve (`tensegrity_opt.imperfection_sensitivity`): for each
    amplitude `p` the chain made imperfect (`asymmetry`: every segment's rest lengths `L1_0 + p`, `L2_0
    - p`) and the limit load of its dead-load path from its own rest shape, as `/v1/limit-load` computes
    it (guided: the guide through its rest tip): `loads` and `kinds` (`fold`, `bifurcation`,
    `joint_limit`, `none`, `unknown`). `bifurcation` classifies the given chain's bifurcation by its
    buckled arms and `law` is the small-imperfection law fitted where one applies (the 2/3 power of an
    unstable-symmetric bifurcation). Not the fold curve of `/v1/stability-boundary`, whose guide stays
    fixed. Pseudo-arclength continuation (`tensegrity_opt.analyses.paths.branches`): chains of up to 64
    segments (longer: 422 `invalid_parameter` on `manipulator.n`); `max_points` up to the server's
    `TENSEGRITY_MAX_PATH_POINTS` (default 5000; above: 422 `too_many_points`). The computation stops
    shortly before the server's time limit and answers what it has (200, `status: "time_limit"`,
    `success: false`) instead of a 504.

    Args:
        body (ImperfectionSensitivityRequest): The limit load of each imperfect chain's dead-load
            path from its rest shape, against the imperfection's
            amplitude (`tensegrity_opt.imperfection_sensitivity`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | ImperfectionSensitivityOut]
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
    body: ImperfectionSensitivityRequest,
) -> ErrorOut | ImperfectionSensitivityOut | None:
    """The limit load an imperfect arm reaches, against the imperfection's amplitude

     Koiter's imperfection-sensitivity curve (`tensegrity_opt.imperfection_sensitivity`): for each
    amplitude `p` the chain made imperfect (`asymmetry`: every segment's rest lengths `L1_0 + p`, `L2_0
    - p`) and the limit load of its dead-load path from its own rest shape, as `/v1/limit-load` computes
    it (guided: the guide through its rest tip): `loads` and `kinds` (`fold`, `bifurcation`,
    `joint_limit`, `none`, `unknown`). `bifurcation` classifies the given chain's bifurcation by its
    buckled arms and `law` is the small-imperfection law fitted where one applies (the 2/3 power of an
    unstable-symmetric bifurcation). Not the fold curve of `/v1/stability-boundary`, whose guide stays
    fixed. Pseudo-arclength continuation (`tensegrity_opt.analyses.paths.branches`): chains of up to 64
    segments (longer: 422 `invalid_parameter` on `manipulator.n`); `max_points` up to the server's
    `TENSEGRITY_MAX_PATH_POINTS` (default 5000; above: 422 `too_many_points`). The computation stops
    shortly before the server's time limit and answers what it has (200, `status: "time_limit"`,
    `success: false`) instead of a 504.

    Args:
        body (ImperfectionSensitivityRequest): The limit load of each imperfect chain's dead-load
            path from its rest shape, against the imperfection's
            amplitude (`tensegrity_opt.imperfection_sensitivity`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | ImperfectionSensitivityOut
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: ImperfectionSensitivityRequest,
) -> Response[ErrorOut | ImperfectionSensitivityOut]:
    """The limit load an imperfect arm reaches, against the imperfection's amplitude

     Koiter's imperfection-sensitivity curve (`tensegrity_opt.imperfection_sensitivity`): for each
    amplitude `p` the chain made imperfect (`asymmetry`: every segment's rest lengths `L1_0 + p`, `L2_0
    - p`) and the limit load of its dead-load path from its own rest shape, as `/v1/limit-load` computes
    it (guided: the guide through its rest tip): `loads` and `kinds` (`fold`, `bifurcation`,
    `joint_limit`, `none`, `unknown`). `bifurcation` classifies the given chain's bifurcation by its
    buckled arms and `law` is the small-imperfection law fitted where one applies (the 2/3 power of an
    unstable-symmetric bifurcation). Not the fold curve of `/v1/stability-boundary`, whose guide stays
    fixed. Pseudo-arclength continuation (`tensegrity_opt.analyses.paths.branches`): chains of up to 64
    segments (longer: 422 `invalid_parameter` on `manipulator.n`); `max_points` up to the server's
    `TENSEGRITY_MAX_PATH_POINTS` (default 5000; above: 422 `too_many_points`). The computation stops
    shortly before the server's time limit and answers what it has (200, `status: "time_limit"`,
    `success: false`) instead of a 504.

    Args:
        body (ImperfectionSensitivityRequest): The limit load of each imperfect chain's dead-load
            path from its rest shape, against the imperfection's
            amplitude (`tensegrity_opt.imperfection_sensitivity`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | ImperfectionSensitivityOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: ImperfectionSensitivityRequest,
) -> ErrorOut | ImperfectionSensitivityOut | None:
    """The limit load an imperfect arm reaches, against the imperfection's amplitude

     Koiter's imperfection-sensitivity curve (`tensegrity_opt.imperfection_sensitivity`): for each
    amplitude `p` the chain made imperfect (`asymmetry`: every segment's rest lengths `L1_0 + p`, `L2_0
    - p`) and the limit load of its dead-load path from its own rest shape, as `/v1/limit-load` computes
    it (guided: the guide through its rest tip): `loads` and `kinds` (`fold`, `bifurcation`,
    `joint_limit`, `none`, `unknown`). `bifurcation` classifies the given chain's bifurcation by its
    buckled arms and `law` is the small-imperfection law fitted where one applies (the 2/3 power of an
    unstable-symmetric bifurcation). Not the fold curve of `/v1/stability-boundary`, whose guide stays
    fixed. Pseudo-arclength continuation (`tensegrity_opt.analyses.paths.branches`): chains of up to 64
    segments (longer: 422 `invalid_parameter` on `manipulator.n`); `max_points` up to the server's
    `TENSEGRITY_MAX_PATH_POINTS` (default 5000; above: 422 `too_many_points`). The computation stops
    shortly before the server's time limit and answers what it has (200, `status: "time_limit"`,
    `success: false`) instead of a 504.

    Args:
        body (ImperfectionSensitivityRequest): The limit load of each imperfect chain's dead-load
            path from its rest shape, against the imperfection's
            amplitude (`tensegrity_opt.imperfection_sensitivity`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | ImperfectionSensitivityOut
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
